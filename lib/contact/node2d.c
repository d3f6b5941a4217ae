/* node2d.c - node-to-segment contact geometry in 2D.  See node2d.h. */
#include "contact/node2d.h"

#include <math.h>

int dem_node_segment(const double P[2], const double A[2], const double B[2], double dmax, double tol,
		     dem_node_seg_t *out)
{
	double tx = B[0] - A[0], ty = B[1] - A[1], L = hypot(tx, ty);
	if (!(L > 0))
		return 0;
	tx /= L, ty /= L;
	double rx = P[0] - A[0], ry = P[1] - A[1];
	double g = rx * ty - ry * tx;  /* -(P - A) . nf, nf = (-t_y, t_x) */
	if (!(g > 0) || !(g < dmax))
		return 0;
	double xi = (rx * tx + ry * ty) / L;
	if (!(xi >= -tol) || !(xi <= 1 + tol))
		return 0;
	out->g = g;
	out->xi = xi < 0 ? 0 : xi > 1 ? 1 : xi;
	out->n[0] = -ty, out->n[1] = tx;
	out->L = L;
	return 1;
}
