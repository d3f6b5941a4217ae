/* sphere.c - sphere/sphere contact (Han 2004, Ch. 3.2.2, 3.4.2).  See
 * sphere.h. */
#include "contact/sphere.h"

#include <math.h>

#include "contact/vec3.h"

int dem_contact_sphere_sphere(const dem_contact_model_t *cm, const dem_sphere_t *s1,
                              const dem_sphere_t *s2, double kn, double meff, double dt,
                              dem_contact_state_t *st, dem_pair_out_t *out)
{
	double d[3];
	v3_sub(s2->x, s1->x, d);
	double dist = v3_norm(d), delta = s1->R + s2->R - dist;
	if (!(delta > 0) || !(dist > 0)) {
		dem_contact_state_reset(st);
		return 0;
	}
	dem_contact_kin_t k;
	double r1[3], w1[3], w2[3];
	double a1 = s1->R - 0.5 * delta;  /* |C - O1| */
	for (int i = 0; i < 3; i++) {
		k.n[i] = out->n[i] = d[i] / dist;
		out->C[i] = s1->x[i] + a1 * k.n[i];
		r1[i] = out->C[i] - s1->x[i];
		k.r[i] = out->C[i] - s2->x[i];
	}
	/* Eqs. 3.54-3.56 with the arms from the centres to C */
	v3_cross(s1->w, r1, w1);
	v3_cross(s2->w, k.r, w2);
	for (int i = 0; i < 3; i++)
		k.vrel[i] = s2->v[i] + w2[i] - s1->v[i] - w1[i];
	k.wn = (s2->w[0] - s1->w[0]) * k.n[0] + (s2->w[1] - s1->w[1]) * k.n[1]
	       + (s2->w[2] - s1->w[2]) * k.n[2];  /* Eq. 3.59 */
	k.delta = delta;
	k.gamma = 1;
	k.kn = kn;
	k.meff = meff;
	k.dt = dt;
	out->delta = delta;
	cm->kernel(cm, &k, st, &out->c);
	double mF[3] = { -out->c.F[0], -out->c.F[1], -out->c.F[2] };
	v3_cross(r1, mF, out->T1);
	return 1;
}
