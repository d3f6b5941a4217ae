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
 * same tree is built here top down, as in asdt.c: a node's points, kept in
 * input order, give their first to the node and are split stably by the key
 * into those of its two children.  Done in place this lays the nodes out in
 * preorder in one array; each node records the end of its subtree.
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
#include "detect/detect.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* HOT: inlined into each instance per dimension, so that the loops over
 * the axes have constant trip counts. */
#if defined(__GNUC__)
#define HOT static inline __attribute__((always_inline))
#else
#define HOT static inline
#endif

/* The arrays are made of slots: a coordinate, or two 32-bit numbers. */
typedef union slot {
	double x;
	uint32_t u[2];
} slot_t;

/* Layouts, for dimension D (a constant in each instance of the code):
 *   item (build): p = (a, b) (2D), then {box number}            2D + 1 slots
 *   node (tree):  region: min a, max b (2D), p (2D),
 *                 then {end of subtree, box number}             4D + 1 slots
 * The items live in the block of the nodes until the nodes replace them. */
#define ITEM(d) (2 * (d) + 1)
#define NODE(d) (4 * (d) + 1)

/* A pending range of the build: the items [s, e) form the subtree whose
 * region is (c, d) in E^2n and whose root bisects axis j. */
typedef struct range {
	uint32_t s, e;
	int j;
	double c[2 * DEM_MAXDIM], d[2 * DEM_MAXDIM];
} range_t;

/* Copies item i to l (<= i) and to tmp[r]; returns 1 when it goes left of
 * key on axis j.  The caller advances l or r: no branch to mispredict. */
HOT unsigned split_one(slot_t *it, slot_t *tmp, uint32_t i, uint32_t l,
		       uint32_t r, int j, double key, const int dim)
{
	slot_t v[2 * DEM_MAXDIM + 1];
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
	const int w = ITEM(dim), m = 2 * dim;
	range_t stack[64];
	int sp = 0;
	range_t r = {.s = 0, .e = n, .j = 0};

	for (int j = 0; j < m; j++) {
		r.c[j] = c0[j];
		r.d[j] = d0[j];
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
					slot_t t[2 * DEM_MAXDIM + 1];
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
		const int jn = j + 1 == m ? 0 : j + 1;
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

/* x = (lower a, upper b) lies in the search region S of t = (a, b):
 * a <= b_t and b >= a_t (Eq. 2.4, 2.5). */
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
			/* the region (Eq. 2.6) against S: skip the subtree
			 * or test the point and step into it */
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

HOT int adt(const dem_boxes_t *b, dem_pairs_t *out, dem_detect_stats_t *st,
	    const int dim)
{
	const uint32_t n = (uint32_t)b->n;
	const int w = NODE(dim), wi = ITEM(dim), m = 2 * dim;
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
	build(it, tmp, n, c0, d0, end, dim);
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
