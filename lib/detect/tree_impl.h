/* tree_impl.h - the binary tree the ADT (adt.c) and the ASDT (asdt.c)
 * share: its slots and node layout, its top-down build and its search.
 * Included by those two files only: every function is static and inlined
 * into each instance per dimension.
 *
 * A tree over N points of M keys (a box's two corners, M = 2D, in the
 * ADT; its lower corner, M = D, in the ASDT) is built top down: a node's
 * points, kept in input order, give their first to the node and are split
 * stably by the node's key into the points of its two children.  Done in
 * place this lays the nodes out in preorder in one array: a node's first
 * child follows it, and each node records the end of its subtree.
 */
#ifndef DEM_DETECT_TREE_IMPL_H
#define DEM_DETECT_TREE_IMPL_H

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "detect/boxes.h"

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

/* Layouts, for dimension D (a constant in each instance of the code) and
 * M keys a point (2D in the ADT, D in the ASDT):
 *   item (build): the point's M coordinates, then {box number}  M + 1 slots
 *   node (tree):  a region: lower, upper (2D), the box: lower, upper (2D),
 *                 then {end of subtree, box number}             4D + 1 slots
 * (what the region bounds is each tree's own, adt.c and asdt.c). */
#define ITEM(m) ((m) + 1)
#define NODE(d) (4 * (d) + 1)

/* A pending range of the build: the items [s, e) form the subtree whose
 * region is (c, d) in the space of the points and whose root bisects
 * axis j. */
typedef struct range {
	uint32_t s, e;
	int j;
	double c[2 * DEM_MAXDIM], d[2 * DEM_MAXDIM];
} range_t;

/* Copies item i to l (<= i) and to tmp[r]; returns 1 when it goes left of
 * key on axis j.  The caller advances l or r: no branch to mispredict. */
HOT unsigned split_one(slot_t *it, slot_t *tmp, uint32_t i, uint32_t l,
		       uint32_t r, int j, double key, const int m)
{
	slot_t v[2 * DEM_MAXDIM + 1];
	const int w = ITEM(m);

	memcpy(v, it + (size_t)i * w, w * sizeof *v);
	memcpy(it + (size_t)l * w, v, w * sizeof *v);
	memcpy(tmp + (size_t)r * w, v, w * sizeof *v);
	return v[j].x < key;
}

/* Builds the tree over the items it[0 .. n-1] (points of m keys), in
 * input order: a node bisects its region across axis j = level mod m at
 * its middle (Eq. 2.1, 2.2), and a point goes left when its key j is less.
 * Leaves the items in preorder and the end of each node's subtree in
 * end[].  tmp holds n items. */
HOT void build(slot_t *it, slot_t *tmp, uint32_t n, const double *c0,
	       const double *d0, uint32_t *end, const int m)
{
	const int w = ITEM(m);
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
			unsigned left = split_one(it, tmp, i, l, nr, j, key, m);
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

/* x = (lower, upper) meets box t = (lower, upper), both closed: Eq. 2.4;
 * with the ADT's regions, Eq. 2.5's test of the search region S. */
HOT unsigned overlap(const slot_t *x, const double *t, const int dim)
{
	unsigned in = 1;
	for (int d = 0; d < dim; d++)
		in &= (x[d].x <= t[dim + d]) & (x[dim + d].x >= t[d]);
	return in;
}

/* Node k's region x widened to take in its children's, k + 1 and the
 * ends of their subtrees: a sweep of the nodes from the back (postorder,
 * Fig. 2.6) meets them done. */
HOT void widen(const slot_t *nd, slot_t *x, uint32_t k, const uint32_t *end, const int dim)
{
	const int w = NODE(dim);

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
			/* the subtree's region (ADT: Eq. 2.6, ASDT: E_k of
			 * Eq. 2.7) against box p: skip the subtree or test
			 * the box and step into it */
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

/* The search, counted in st (may be NULL); frees the nodes.  DEM_EIO when
 * the pairs ran out of memory. */
HOT int search_all(slot_t *nd, uint32_t n, dem_pairs_t *out, dem_detect_stats_t *st,
		   const int dim)
{
	size_t checks = search(nd, n, out, dim);
	if (st)
		st->checks += checks;
	free(nd);
	return out->nomem ? DEM_EIO : DEM_OK;
}

#endif
