/* asdt.c - augmented spatial digital tree (ASDT) contact detection,
 * Ch. 2.3.3, after Feng and Owen (2002).
 *
 * A box is represented by its lower corner a alone, a point in E^n, with
 * the upper corner b carried as augmented data.  The points go into a
 * spatial binary tree in input order, bisecting the bounding region of the
 * lower corners, D~_0, across the n axes in turn (Eq. 2.1, 2.2 with n in
 * place of 2n).  The node of box i is node i, so the tree is two arrays
 * (per node: E_k and its box; its two children) and no node is allocated
 * on its own.
 *
 * Each node k also carries E_k, the bounding box of all the boxes stored in
 * its subtree (Eq. 2.7), and the search walks the tree in preorder, skipping
 * a subtree whose E_k misses the target box: at most n pairs of comparisons
 * a node.
 *
 * Each pair once: box i first searches the tree of boxes 0 .. i-1 and is
 * then inserted.  Inserting box i unions it into E_k of every node on its
 * insertion path, which are exactly the subtrees that gain it, so every
 * E_k always equals Eq. 2.7 over the current tree: the postorder pass of
 * Fig. 2.6 is done incrementally.
 *
 * Trees can be degenerate (identical boxes make a chain N deep), so the
 * walk uses an explicit stack of at most N + 1 entries, never recursion.
 * Memory O(N); time O(N log N) for well spread boxes.
 */
#include "detect/detect.h"

#include <math.h>
#include <stdlib.h>

#define NONE UINT32_MAX

int dem_detect_asdt(const dem_boxes_t *b, dem_pairs_t *out,
		    dem_detect_stats_t *st)
{
	const size_t n = b->n;
	const int dim = b->dim;
	/* per node, 4n doubles: E_k (lower, upper corner), then the box */
	const size_t s = 4 * (size_t)dim;

	if (n < 2)
		return DEM_OK;
	double *nd = malloc(n * s * sizeof *nd);
	uint32_t *kid = malloc(2 * n * sizeof *kid);
	uint32_t *stack = malloc((n + 1) * sizeof *stack);
	int rc = DEM_EIO;

	if (!nd || !kid || !stack)
		goto done;

	/* D~_0: the bounding box of the lower corners */
	double c0[DEM_MAXDIM], d0[DEM_MAXDIM];
	for (int d = 0; d < dim; d++) {
		c0[d] = HUGE_VAL;
		d0[d] = -HUGE_VAL;
	}
	for (size_t i = 0; i < n; i++) {
		double *v = nd + i * s;
		for (int d = 0; d < dim; d++) {
			v[2 * dim + d] = b->lo[d][i];
			v[3 * dim + d] = b->hi[d][i];
			v[d] = v[2 * dim + d];    /* E_k of a leaf: its box */
			v[dim + d] = v[3 * dim + d];
			c0[d] = fmin(c0[d], v[2 * dim + d]);
			d0[d] = fmax(d0[d], v[2 * dim + d]);
		}
		kid[2 * i] = kid[2 * i + 1] = NONE;
	}

	size_t checks = 0;
	for (size_t t = 1; t < n; t++) {
		const double *bt = nd + t * s + 2 * dim;   /* (a_t, b_t) */

		/* Region search in preorder over boxes 0 .. t-1. */
		size_t sp = 0;
		stack[sp++] = 0;
		while (sp) {
			uint32_t k = stack[--sp];
			const double *v = nd + (size_t)k * s;
			int in = 1;
			/* E_k (Eq. 2.7) against the target box */
			for (int d = 0; d < dim; d++)
				in &= (v[d] <= bt[dim + d]) & (v[dim + d] >= bt[d]);
			if (!in)
				continue;
			const double *bk = v + 2 * dim;
			int hit = 1;
			for (int d = 0; d < dim; d++)
				hit &= (bk[d] <= bt[dim + d]) & (bk[dim + d] >= bt[d]);
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

		/* Insertion of the lower corner (Eq. 2.1, 2.2 in E^n),
		 * growing E_k along the path (Eq. 2.7). */
		double c[DEM_MAXDIM], dd[DEM_MAXDIM];     /* D~_k */
		for (int d = 0; d < dim; d++) {
			c[d] = c0[d];
			dd[d] = d0[d];
		}
		uint32_t k = 0;
		int j = 0;
		for (;;) {
			double *v = nd + (size_t)k * s;
			for (int d = 0; d < dim; d++) {
				v[d] = fmin(v[d], bt[d]);
				v[dim + d] = fmax(v[dim + d], bt[dim + d]);
			}
			double key = 0.5 * c[j] + 0.5 * dd[j];
			unsigned right = !(bt[j] < key);
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
			if (++j == dim)
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
