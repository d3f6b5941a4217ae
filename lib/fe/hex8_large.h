/* hex8_large.h - the implicit hexahedron with geometric nonlinearity, for
 * the large-strain option of demform (Ch. 8.5.2: "both geometric and
 * material nonlinearities can be taken into account").
 *
 * Total Lagrangian: the Green-Lagrange strain E = (F^T F - I)/2 and the
 * second Piola-Kirchhoff stress S, integrated over the reference
 * configuration with 2x2x2 Gauss points.  The material law is the one of
 * material.h applied to (E, S) - a St Venant-Kirchhoff extension of the
 * small-strain J2 model, right for the small strains and large rotations
 * of a formed plate.  Against bending locking the element carries the
 * incompatible modes of DEM_HEX8_EAS (hex8.h) as additional displacement
 * gradients in F (Wilson's modes 1 - xi_m^2 with the centre Jacobian and
 * the det J0 / det J scaling), condensed exactly at element level.  With
 * zero displacements it has the tangent of dem_hex8_static(); the test
 * checks that, and the tangent against finite differences.
 *
 * Array conventions are those of hex8.h (component-major nodal arrays,
 * Voigt vectors with engineering shears; hist->sig holds S).
 */
#ifndef DEM_FE_HEX8_LARGE_H
#define DEM_FE_HEX8_LARGE_H

#include "fe/hex8.h"

/* Internal force and consistent tangent (material + geometric stiffness)
 * for the total displacement un + du, un being the displacement of the
 * converged state hn (S, ep, mode amplitudes).  eas: with the incompatible
 * modes (else the plain displacement element).  h->alpha is the starting
 * guess of the local mode iteration (as in dem_hex8_static) and returns
 * converged; fint = int B_NL^T S dV0; K may be NULL; *wp (may be NULL) the
 * plastic work of the increment.  Returns DEM_HEX8_OK, DEM_HEX8_INVERTED
 * (reference element bad, or det F <= 0 at a Gauss point) or
 * DEM_HEX8_NOCONV. */
int dem_hex8_large(const dem_mat_t *m, int eas, const double X[24],
		   const double un[24], const double du[24],
		   const dem_hex8_hist_t *hn, dem_hex8_hist_t *h,
		   double fint[24], double K[576], double *wp);

#endif
