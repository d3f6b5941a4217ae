/* sphere.h - sphere/sphere contact (Han 2004, Ch. 3.2.2, Fig. 3.11).
 *
 * Overlap delta = R1 + R2 - |O2 - O1| (Eq. 3.8 in 3D), normal n from
 * sphere 1 (the target) to sphere 2 (the contactor), contact point C in the
 * middle of the overlap on the line of centres, law coefficient
 * k_n = dem_law_kn(law, R1 R2 / (R1 + R2)), equivalent mass M1 M2/(M1+M2).
 */
#ifndef DEM_CONTACT_SPHERE_H
#define DEM_CONTACT_SPHERE_H

#include "contact/facet.h"

typedef struct dem_pair_out {
	double delta;
	double n[3];          /* unit normal 1 -> 2 */
	double C[3];          /* contact point */
	dem_contact_out_t c;  /* force and torque on sphere 2 */
	double T1[3];         /* torque on sphere 1 (its force is -c.F) */
} dem_pair_out_t;

/* One pair at one step.  kn: the pair's k_n; meff: the equivalent mass.
 * Returns 1 in contact (out filled), 0 otherwise (state reset). */
int dem_contact_sphere_sphere(const dem_contact_model_t *cm, const dem_sphere_t *s1,
                              const dem_sphere_t *s2, double kn, double meff, double dt,
                              dem_contact_state_t *st, dem_pair_out_t *out);

#endif
