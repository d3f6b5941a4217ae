/* units.h - physical quantities with units, converted to SI.
 *
 * A quantity is a number optionally followed by a unit expression:
 * "0.7 mm", "46.5 m/s", "72 GPa", "7800 kg/m^3", "30 deg", "9.81 m/s^2".
 * A bare number is taken in SI units of the expected dimension.
 * Angles convert to radians.  Temperatures are in kelvin ("293 K"): an
 * offset scale (degC) is not a unit of this algebra and is refused.
 */
#ifndef DEM_CORE_UNITS_H
#define DEM_CORE_UNITS_H

#include <stddef.h>

/* A physical dimension as exponents of length, mass, time, angle and
 * temperature (Th, for the Theta of the SI brochure; T is time). */
typedef struct dem_dim {
	signed char L, M, T, A, Th;
} dem_dim_t;

#define DEM_DIM_NONE     ((dem_dim_t){0, 0, 0, 0, 0})
#define DEM_DIM_LENGTH   ((dem_dim_t){1, 0, 0, 0, 0})
#define DEM_DIM_MASS     ((dem_dim_t){0, 1, 0, 0, 0})
#define DEM_DIM_TIME     ((dem_dim_t){0, 0, 1, 0, 0})
#define DEM_DIM_ANGLE    ((dem_dim_t){0, 0, 0, 1, 0})
#define DEM_DIM_VELOCITY ((dem_dim_t){1, 0, -1, 0, 0})
#define DEM_DIM_ACCEL    ((dem_dim_t){1, 0, -2, 0, 0})
#define DEM_DIM_FORCE    ((dem_dim_t){1, 1, -2, 0, 0})
#define DEM_DIM_PRESSURE ((dem_dim_t){-1, 1, -2, 0, 0})
#define DEM_DIM_DENSITY  ((dem_dim_t){-3, 1, 0, 0, 0})
#define DEM_DIM_RATE     ((dem_dim_t){0, 0, -1, 0, 0})
#define DEM_DIM_TEMPERATURE ((dem_dim_t){0, 0, 0, 0, 1})

int dem_dim_equal(dem_dim_t a, dem_dim_t b);

/* The SI unit of a dimension as text ("m", "Pa", "kg/m^3", "rad", "" for
 * none), for messages and --dump-scene. */
const char *dem_dim_si_name(dem_dim_t d);

/* The names above cover the toolkit's common dimensions (those defined here,
 * and m^2, m^3, N/m, rad/s); for any other dimension dem_dim_si_name() gives
 * "?", since building a generic form needs storage: dem_dim_format() writes
 * any dimension into buf, the generic form as "m^-1 kg s^-1" (factors in
 * the order m, kg, s, rad, K), which dem_units_parse reads back.  Both
 * return buf. */
const char *dem_dim_format(dem_dim_t d, char *buf, size_t len);

/* The dimension in words for messages: "a length", "an acceleration", "a
 * number" (plural: "lengths", ...), or "a quantity in m^-1 kg s^-1". */
const char *dem_dim_describe(dem_dim_t d, int plural, char *buf, size_t len);

/* A typical value with a unit, for messages: "46.5 m/s", "0.7 mm". */
const char *dem_dim_example(dem_dim_t d, char *buf, size_t len);

/* Parse text as a quantity of dimension want; on success store the SI value
 * in *si and return 0.  On failure return -1 and write a one-line reason
 * ("unknown unit 'mmm'", "unit 's' is a time, expected a length", "not a
 * number", "not finite") into why. */
int dem_units_parse(const char *text, dem_dim_t want, double *si,
		    char *why, size_t whylen);

#endif
