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
 * key into the points of its two children.  Done in place this lays the
 * nodes out in preorder in one array: a node's first child follows it,
 * and each node records the end of its subtree.  (Insertion follows N
 * random paths through an array larger than the caches; the split streams
 * through it.)
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
#include "detect/detect.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* HOT: inlined into each instance per dimension, so that the loops over
 * the axes have constant trip counts. */
#if defined(__GNUC__)
#define HOT static inline __attribute__((always_inline))
#define PREFETCH(p) __builtin_prefetch(p)
#else
#define HOT static inline
#define PREFETCH(p) ((void)(p))
#endif

/* The arrays are made of slots: a coordinate, or two 32-bit numbers. */
typedef union slot {
	double x;
	uint32_t u[2];
} slot_t;

/* Layouts, for dimension D (a constant in each instance of the code):
 *   item (build): a (D), then {box number}                      D + 1 slots
 *   node (tree):  E_k lo, hi (2D), box lo, hi (2D),
 *                 then {end of subtree, box number}             4D + 1 slots
 * The nodes take one block; the items and the split's buffer live in it
 * until the nodes replace them, 2 (D + 1) <= 4D + 1. */
#define ITEM(d) ((d) + 1)
#define NODE(d) (4 * (d) + 1)

/* A pending range of the build: the items [s, e) form the subtree whose
 * region is (c, d) and whose root bisects axis j. */
typedef struct range {
	uint32_t s, e;
	int j;
	double c[DEM_MAXDIM], d[DEM_MAXDIM];
} range_t;

/* Copies item i to l (<= i) and to tmp[r]; returns 1 when it goes left of
 * key on axis j.  The caller advances l or r: no branch to mispredict. */
HOT unsigned split_one(slot_t *it, slot_t *tmp, uint32_t i, uint32_t l,
		       uint32_t r, int j, double key, const int dim)
{
	slot_t v[DEM_MAXDIM + 1];
	const int w = ITEM(dim);

	memcpy(v, it + (size_t)i * w, w * sizeof *v);
	memcpy(it + (size_t)l * w, v, w * sizeof *v);
	memcpy(tmp + (size_t)r * w, v, w * sizeof *v);
	return v[j].x < key;
}

/* Builds the tree over the items it[0 .. n-1], in input order: leaves
 * them in preorder and the end of each node's subtree in end[].  tmp holds
 * n items. */
HOT void build(slot_t *it, slot_t *tmp, uint32_t n, const double *c0,
	       const double *d0, uint32_t *end, const int dim)
{
	const int w = ITEM(dim);
	range_t stack[64];
	int sp = 0;
	range_t r = {.s = 0, .e = n, .j = 0};

	for (int d = 0; d < dim; d++) {
		r.c[d] = c0[d];
		r.d[d] = d0[d];
	}
	for (;;) {
		const uint32_t s = r.s, e = r.e;
		const int j = r.j;
		const double key = 0.5 * r.c[j] + 0.5 * r.d[j];   /* x_k^j */
		end[s] = e;
		if (e - s <= 3) {
			/* Most nodes: below s at most a pair, which is a
			 * chain unless it splits, and then only its order
			 * may change. */
			if (e - s == 3) {
				slot_t *u = it + (size_t)(s + 1) * w;
				slot_t *v = u + w;
				unsigned lu = u[j].x < key, lv = v[j].x < key;
				if (!lu && lv) {
					slot_t t[DEM_MAXDIM + 1];
					memcpy(t, u, w * sizeof *t);
					memcpy(u, v, w * sizeof *t);
					memcpy(v, t, w * sizeof *t);
				}
				end[s + 1] = lu != lv ? s + 2 : e;
				end[s + 2] = e;
			} else if (e - s == 2) {
				end[s + 1] = e;
			}
			if (!sp)
				break;
			r = stack[--sp];
			continue;
		}
		/* Eq. 2.2: split at the key, in input order within each half
		 * (left in place, right through tmp) */
		uint32_t l = s + 1, nr = 0;
		for (uint32_t i = s + 1; i < e; i++) {
			unsigned left = split_one(it, tmp, i, l, nr, j, key,
						  dim);
			l += left;
			nr += !left;
		}
		memcpy(it + (size_t)l * w, tmp, (size_t)nr * w * sizeof *tmp);
		/* children: [s+1, l) left, [l, e) right; the larger waits */
		const int jn = j + 1 == dim ? 0 : j + 1;
		const int big_left = l - (s + 1) > e - l;
		if (l > s + 1 && e > l) {
			range_t *q = &stack[sp++];
			*q = r;
			q->j = jn;
			if (big_left) {
				q->s = s + 1;
				q->e = l;
				q->d[j] = key;
			} else {
				q->s = l;
				q->c[j] = key;
			}
		}
		r.j = jn;
		if (l > s + 1 && !(e > l && big_left)) {
			r.s = s + 1;
			r.e = l;
			r.d[j] = key;
		} else {
			r.s = l;
			r.c[j] = key;
		}
	}
}

/* Closed boxes x and t (lower corner, upper corner) overlap: Eq. 2.4. */
HOT unsigned overlap(const slot_t *x, const double *t, const int dim)
{
	unsigned in = 1;
	for (int d = 0; d < dim; d++)
		in &= (x[d].x <= t[dim + d]) & (x[dim + d].x >= t[d]);
	return in;
}

/* The region search of every box against the nodes after it. */
HOT size_t search(const slot_t *nd, uint32_t n, dem_pairs_t *out,
		  const int dim)
{
	const int w = NODE(dim);
	size_t checks = 0;

	for (uint32_t p = 0; p + 1 < n; p++) {
		const slot_t *np = nd + (size_t)p * w;
		double t[2 * DEM_MAXDIM];
		for (int d = 0; d < 2 * dim; d++)
			t[d] = np[2 * dim + d].x;
		const uint32_t ip = np[4 * dim].u[1];
		uint32_t k = p + 1;
		while (k < n) {
			const slot_t *x = nd + (size_t)k * w;
			/* E_k (Eq. 2.7) against box p: skip the subtree or
			 * test the box and step into it */
			unsigned in = overlap(x, t, dim);
			unsigned hit = in & overlap(x + 2 * dim, t, dim);
			checks += in;
			if (hit)
				dem_pairs_push(out, ip, x[4 * dim].u[1]);
			k = in ? k + 1 : x[4 * dim].u[0];
		}
		if (out->nomem)
			break;
	}
	return checks;
}

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
		for (uint32_t c = k + 1; c < end[k]; c = end[c]) {
			const slot_t *y = nd + (size_t)c * w;
			for (int d = 0; d < dim; d++) {
				if (y[d].x < x[d].x)
					x[d].x = y[d].x;
				if (y[dim + d].x > x[dim + d].x)
					x[dim + d].x = y[dim + d].x;
			}
		}
	}
	free(end);

	size_t checks = search(nd, n, out, dim);
	if (st)
		st->checks += checks;
	free(nd);
	return out->nomem ? DEM_EIO : DEM_OK;
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
