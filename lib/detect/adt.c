/* adt.c - alternating digital tree (ADT) contact detection, Ch. 2.3.2,
 * after Bonet and Peraire (1991).
 *
 * A box (a, b) in E^n is the point p = (a^1..a^n, b^1..b^n) in E^2n.  The
 * points form a spatial binary tree: a node of level k bisects its region
 * D_k across axis j = k mod 2n at its middle (Eq. 2.1, 2.2); a point goes
 * left when p^j < key.
 *
 * Tree generation.  Inserting the points one at a time in input order, as
 * the thesis does, leaves at each node the first point (in input order) of
 * all those that reach it and sends the others on by the node's key.  The
 * same tree is built here top down, by the build the ASDT shares
 * (tree_impl.h): a node's points, kept in input order, give their first to
 * the node and are split stably by the key into those of its two children.
 * Done in place this lays the nodes out in preorder in one array; each node
 * records the end of its subtree.  The node's region is (min a, max b) of
 * its subtree, its box p; the items live in the block of the nodes until
 * the nodes replace them.
 *
 * Search: box t overlaps box p iff a <= x_max and b >= x_min (Eq. 2.3, 2.4),
 * i.e. p lies in the region S of Eq. 2.5.  A subtree is skipped when its
 * region misses S.  The regions used are the tightened ones of Eq. 2.6, the
 * bounding boxes of the points in each subtree, found by the postorder pass
 * (a sweep of the array from the back).  S reaches down to c_0 in a and up
 * to d_0 in b, so only the lower bound of a and the upper bound of b of a
 * region can ever exclude it; those 2n numbers are all that is kept per
 * node.
 *
 * Each pair once: box p (in preorder) looks only at the nodes after it, so
 * a pair is met from its earlier node alone.  Those nodes are the subtrees
 * of p's children and then the subtrees right of p's path from the root,
 * one after the other in the array; the walk from p + 1 steps into a
 * subtree (to k + 1) when its region meets S and jumps over it (to the end
 * of the subtree) when it does not.  No stack, memory read forward only;
 * the boxes search in preorder, so consecutive searches walk the same parts
 * of the array, and the pairs come out in an order set by the input alone.
 *
 * Trees can be degenerate (identical boxes make a chain N deep); the build
 * keeps the larger of two ranges for later, so its stack stays below 64
 * entries.  Memory O(N); time O(N log N) for well spread boxes.
 */
#include "detect/algo.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "detect/tree_impl.h"

HOT int adt(const dem_boxes_t *b, dem_pairs_t *out, dem_detect_stats_t *st,
	    const int dim)
{
	const uint32_t n = (uint32_t)b->n;
	const int m = 2 * dim, w = NODE(dim), wi = ITEM(m);
	slot_t *nd = malloc((size_t)n * w * sizeof *nd);
	slot_t *tmp = malloc((size_t)n * wi * sizeof *tmp);
	uint32_t *end = malloc((size_t)n * sizeof *end);

	if (!nd || !tmp || !end) {
		free(nd);
		free(tmp);
		free(end);
		return DEM_EIO;
	}
	slot_t *it = nd;

	/* D_0: the bounding box of all points in E^2n */
	double c0[2 * DEM_MAXDIM], d0[2 * DEM_MAXDIM];
	for (int j = 0; j < m; j++) {
		c0[j] = HUGE_VAL;
		d0[j] = -HUGE_VAL;
	}
	for (uint32_t i = 0; i < n; i++) {
		slot_t *v = it + (size_t)i * wi;
		for (int d = 0; d < dim; d++) {
			v[d].x = b->lo[d][i];
			v[dim + d].x = b->hi[d][i];
		}
		for (int j = 0; j < m; j++) {
			c0[j] = v[j].x < c0[j] ? v[j].x : c0[j];
			d0[j] = v[j].x > d0[j] ? v[j].x : d0[j];
		}
		v[m].u[0] = i;
		v[m].u[1] = 0;
	}
	build(it, tmp, n, c0, d0, end, m);
	free(tmp);

	/* Items to nodes, from the back so that node k (which starts at or
	 * after the end of item k - 1) overwrites only items already done,
	 * tightening the regions in postorder (Eq. 2.6): the children of node
	 * k, k + 1 and the end of k + 1's subtree, are done before it. */
	for (uint32_t k = n; k-- > 0;) {
		slot_t v[2 * DEM_MAXDIM + 1];
		memcpy(v, it + (size_t)k * wi, wi * sizeof *v);
		slot_t *x = nd + (size_t)k * w;
		for (int j = 0; j < m; j++)
			x[j].x = x[m + j].x = v[j].x;
		x[2 * m].u[0] = end[k];
		x[2 * m].u[1] = v[m].u[0];
		widen(nd, x, k, end, dim);
	}
	free(end);

	return search_all(nd, n, out, st, dim);
}

int dem_detect_adt(const dem_boxes_t *b, dem_pairs_t *out,
		   dem_detect_stats_t *st)
{
	if (b->n < 2)
		return DEM_OK;
	switch (b->dim) {    /* one instance of the loops per dimension */
	case 1: return adt(b, out, st, 1);
	case 2: return adt(b, out, st, 2);
	default: return adt(b, out, st, 3);
	}
}
