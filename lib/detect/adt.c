/* adt.c - alternating digital tree (ADT) contact detection, Ch. 2.3.2,
 * after Bonet and Peraire (1991).
 *
 * A box (a, b) in E^n is the point p = (a^1..a^n, b^1..b^n) in E^2n.  The
 * points are inserted into a spatial binary tree in input order; the node of
 * box i is node i, so the tree is two arrays (per node: its tightened
 * region and its point; its two children) and no node is allocated on its
 * own.  A node of level k
 * bisects its region D_k across axis j = k mod 2n at its middle (Eq. 2.1,
 * 2.2); a point goes left when p^j < key.
 *
 * Search: box t overlaps box p iff a <= x_max and b >= x_min (Eq. 2.3, 2.4),
 * i.e. p lies in the region S of Eq. 2.5.  The tree is walked in preorder
 * and a subtree is skipped when its region misses S.  The regions used are
 * the tightened ones of Eq. 2.6, the bounding boxes of the points in each
 * subtree.  S reaches down to c_0 in a and up to d_0 in b, so only the
 * lower bound of a and the upper bound of b of a region can ever exclude it;
 * those 2n numbers are all that is kept per node.
 *
 * Each pair once: the boxes are taken in input order, box i first searches
 * the tree of boxes 0 .. i-1 and is then inserted.  Inserting p_i unions it
 * into the region of every node on its insertion path, which are exactly the
 * subtrees that gain p_i, so the regions always equal Eq. 2.6 over the
 * current tree: the postorder tightening pass is done incrementally.
 *
 * Trees can be degenerate (identical boxes make a chain N deep), so the
 * walk uses an explicit stack of at most N + 1 entries, never recursion.
 * Memory O(N); time O(N log N) for well spread boxes.
 */
#include "detect/detect.h"

#include <math.h>
#include <stdlib.h>

#define NONE UINT32_MAX

int dem_detect_adt(const dem_boxes_t *b, dem_pairs_t *out,
		   dem_detect_stats_t *st)
{
	const size_t n = b->n;
	const int dim = b->dim, m = 2 * dim;   /* m: dimension of E^2n */
	/* per node, 2m doubles: the region (min a, max b), then the point
	 * (a, b) */
	const size_t s = 2 * (size_t)m;

	if (n < 2)
		return DEM_OK;
	double *nd = malloc(n * s * sizeof *nd);
	uint32_t *kid = malloc(2 * n * sizeof *kid);
	uint32_t *stack = malloc((n + 1) * sizeof *stack);
	int rc = DEM_EIO;

	if (!nd || !kid || !stack)
		goto done;

	/* D_0: the bounding box of all points in E^2n */
	double c0[2 * DEM_MAXDIM], d0[2 * DEM_MAXDIM];
	for (int j = 0; j < m; j++) {
		c0[j] = HUGE_VAL;
		d0[j] = -HUGE_VAL;
	}
	for (size_t i = 0; i < n; i++) {
		double *v = nd + i * s;
		for (int d = 0; d < dim; d++) {
			v[m + d] = b->lo[d][i];
			v[m + dim + d] = b->hi[d][i];
			v[d] = v[m + d];          /* region: the point itself */
			v[dim + d] = v[m + dim + d];
		}
		for (int j = 0; j < m; j++) {
			c0[j] = fmin(c0[j], v[m + j]);
			d0[j] = fmax(d0[j], v[m + j]);
		}
		kid[2 * i] = kid[2 * i + 1] = NONE;
	}

	size_t checks = 0;
	for (size_t t = 1; t < n; t++) {
		const double *pt = nd + t * s + m;      /* (a_t, b_t) */

		/* Region search (Eq. 2.5) in preorder over boxes 0 .. t-1. */
		size_t sp = 0;
		stack[sp++] = 0;
		while (sp) {
			uint32_t k = stack[--sp];
			const double *v = nd + (size_t)k * s;
			int in = 1;
			/* Eq. 2.6 region against S: min a <= b_t, max b >= a_t */
			for (int d = 0; d < dim; d++)
				in &= (v[d] <= pt[dim + d]) & (v[dim + d] >= pt[d]);
			if (!in)
				continue;
			const double *pk = v + m;
			int hit = 1;
			for (int d = 0; d < dim; d++)
				hit &= (pk[d] <= pt[dim + d]) & (pk[dim + d] >= pt[d]);
			checks++;
			if (hit)
				dem_pairs_push(out, k, (uint32_t)t);
			if (kid[2 * k + 1] != NONE)
				stack[sp++] = kid[2 * k + 1];
			if (kid[2 * k] != NONE)
				stack[sp++] = kid[2 * k];       /* left first */
		}
		if (out->nomem)
			goto done;

		/* Insertion (Eq. 2.1, 2.2), tightening the path (Eq. 2.6). */
		double c[2 * DEM_MAXDIM], dd[2 * DEM_MAXDIM];     /* D_k */
		for (int j = 0; j < m; j++) {
			c[j] = c0[j];
			dd[j] = d0[j];
		}
		uint32_t k = 0;
		int j = 0;
		for (;;) {
			double *v = nd + (size_t)k * s;
			for (int e = 0; e < dim; e++) {
				v[e] = fmin(v[e], pt[e]);
				v[dim + e] = fmax(v[dim + e], pt[dim + e]);
			}
			double key = 0.5 * c[j] + 0.5 * dd[j];
			unsigned right = !(pt[j] < key);
			if (right)
				c[j] = key;
			else
				dd[j] = key;
			uint32_t *slot = &kid[2 * k + right];
			if (*slot == NONE) {
				*slot = (uint32_t)t;
				break;
			}
			k = *slot;
			if (++j == m)
				j = 0;
		}
	}
	if (st)
		st->checks += checks;
	rc = DEM_OK;
done:
	free(nd);
	free(kid);
	free(stack);
	return rc;
}
