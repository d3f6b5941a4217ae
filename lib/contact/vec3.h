/* vec3.h - small 3-vector helpers for lib/contact (internal). */
#ifndef DEM_CONTACT_VEC3_H
#define DEM_CONTACT_VEC3_H

#include <math.h>

static inline double v3_dot(const double a[3], const double b[3])
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline void v3_cross(const double a[3], const double b[3], double c[3])
{
	double x = a[1] * b[2] - a[2] * b[1];
	double y = a[2] * b[0] - a[0] * b[2];
	double z = a[0] * b[1] - a[1] * b[0];
	c[0] = x, c[1] = y, c[2] = z;
}

static inline void v3_sub(const double a[3], const double b[3], double c[3])
{
	c[0] = a[0] - b[0], c[1] = a[1] - b[1], c[2] = a[2] - b[2];
}

static inline double v3_norm(const double a[3])
{
	return sqrt(v3_dot(a, a));
}

#endif
