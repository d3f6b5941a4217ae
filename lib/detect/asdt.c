/* asdt.c - augmented spatial digital tree (ASDT) contact detection,
 * Ch. 2.3.3, after Feng and Owen (2002).
 *
 * A box is represented by its lower corner a alone, a point in E^n, with
 * the upper corner b carried as augmented data.  The points form a spatial
 * binary tree that bisects the bounding region of the lower corners, D~_0,
 * across the n axes in turn at the middle of each node's region (Eq. 2.1,
 * 2.2 with n in place of 2n); a point goes left when a^j < key.
 *
 * Tree generation.  Inserting the points one at a time in input order, as
 * the thesis does, leaves at each node the first point (in input order) of
 * all those that reach it and sends the others on, left or right by the
 * node's key.  The same tree is built here top down: a node's points, kept
 * in input order, give their first to the node and are split stably by the
 * key into the points of its two children (tree_impl.h, shared with the
 * ADT).  Done in place this lays the nodes out in preorder in one array: a
 * node's first child follows it, and each node records the end of its
 * subtree.  (Insertion follows N random paths through an array larger than
 * the caches; the split streams through it.)
 *
 * E_k, the bounding box of all the boxes stored in the subtree of node k
 * (Eq. 2.7), comes from the postorder pass of Fig. 2.6: a sweep of the
 * array from the back meets the children of a node before the node.
 *
 * Search, each pair once.  Box p (in preorder) looks only at the nodes
 * after it in preorder, so a pair is met from its earlier node alone.  Those
 * nodes are the subtrees of p's children and then the subtrees right of
 * p's path from the root, one after the other in the array; the walk from
 * p + 1 tests each subtree's root, steps into the subtree (to k + 1) when its
 * E_k meets box p and jumps over it (to the end of the subtree) when it does
 * not: at most n pairs of comparisons a node, no stack, no test spent on
 * p's ancestors, and memory read forward only.  The boxes search in
 * preorder, so consecutive searches walk the same parts of the array; the
 * pairs come out in that order, which depends on the input alone.
 *
 * Trees can be degenerate (identical boxes make a chain N deep); the build
 * keeps the larger of two ranges for later, so its stack stays below 64
 * entries.  Memory O(N) (76 bytes a box in 2D, 108 in 3D); time O(N log N)
 * for well spread boxes.
 */
#include "detect/algo.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "detect/tree_impl.h"

HOT int asdt(const dem_boxes_t *b, dem_pairs_t *out, dem_detect_stats_t *st,
	     const int dim)
{
	const uint32_t n = (uint32_t)b->n;
	const int w = NODE(dim), wi = ITEM(dim);
	slot_t *nd = malloc((size_t)n * w * sizeof *nd);
	uint32_t *end = malloc((size_t)n * sizeof *end);

	if (!nd || !end) {
		free(nd);
		free(end);
		return DEM_EIO;
	}
	/* the items and the split's buffer live in the block of the nodes
	 * until the nodes (E_k, then the box) replace them: 2 (D + 1) <= 4D + 1 */
	slot_t *it = nd, *tmp = nd + (size_t)n * wi;

	/* D~_0: the bounding box of the lower corners */
	double c0[DEM_MAXDIM], d0[DEM_MAXDIM];
	for (int d = 0; d < dim; d++) {
		c0[d] = HUGE_VAL;
		d0[d] = -HUGE_VAL;
	}
	for (uint32_t i = 0; i < n; i++) {
		slot_t *v = it + (size_t)i * wi;
		for (int d = 0; d < dim; d++) {
			double a = b->lo[d][i];
			v[d].x = a;
			c0[d] = a < c0[d] ? a : c0[d];
			d0[d] = a > d0[d] ? a : d0[d];
		}
		v[dim].u[0] = i;
		v[dim].u[1] = 0;
	}
	build(it, tmp, n, c0, d0, end, dim);

	/* Items to nodes, from the back so that node k (which starts at or
	 * after the end of item k - 1) overwrites only items already done,
	 * with Eq. 2.7 in postorder (Fig. 2.6): the children of node k, k + 1
	 * and the end of k + 1's subtree, are done before it. */
	for (uint32_t k = n; k-- > 0;) {
		slot_t v[DEM_MAXDIM + 1];
		memcpy(v, it + (size_t)k * wi, wi * sizeof *v);
		const uint32_t i = v[dim].u[0];
		if (k >= 16) {  /* the upper corners are read at random */
			uint32_t ia = it[(size_t)(k - 16) * wi + dim].u[0];
			for (int d = 0; d < dim; d++)
				PREFETCH(b->hi[d] + ia);
		}
		slot_t *x = nd + (size_t)k * w;
		for (int d = 0; d < dim; d++) {
			x[d].x = x[2 * dim + d].x = v[d].x;
			x[dim + d].x = x[3 * dim + d].x = b->hi[d][i];
		}
		x[4 * dim].u[0] = end[k];
		x[4 * dim].u[1] = i;
		widen(nd, x, k, end, dim);
	}
	free(end);

	return search_all(nd, n, out, st, dim);
}

int dem_detect_asdt(const dem_boxes_t *b, dem_pairs_t *out,
		    dem_detect_stats_t *st)
{
	if (b->n < 2)
		return DEM_OK;
	switch (b->dim) {    /* one instance of the loops per dimension */
	case 1: return asdt(b, out, st, 1);
	case 2: return asdt(b, out, st, 2);
	default: return asdt(b, out, st, 3);
	}
}
