/* dcell_impl.h - the D-cell mapping and sweeps for one dimension DIM;
 * included by dcell.c once per dimension, so the inner loops have constant
 * trip counts. */
#define CAT_(a, b) a##b
#define CAT(a, b) CAT_(a, b)
#define ENT CAT(ent, DIM)
#define CH CAT(ch, DIM)
#define CTX CAT(ctx, DIM)
#define RAW CAT(raw, DIM)
#define CELLS CAT(cells, DIM)
#define FN(name) CAT(name, DIM)

/* A box in cell order, all the tests need in one place. */
typedef struct ENT {
	double lo[DIM], hi[DIM];
	uint32_t id;            /* index in the caller's box set */
	uint32_t f;             /* bit d: it reaches past its cell along d */
} ENT;

/* Within a cell the boxes are sorted into groups by their migration bits
 * f, read as a number with x as the most significant bit: the boxes that
 * reach the next cell along x, and those that reach it along x and y, are
 * then a suffix of the cell (see sweep_near).  group_f: group -> f. */
#define NG (1 << DIM)
#if DIM == 3
static const unsigned char FN(group_f)[NG] = {0, 4, 2, 6, 1, 5, 3, 7};
#elif DIM == 2
static const unsigned char FN(group_f)[NG] = {0, 2, 1, 3};
#else
static const unsigned char FN(group_f)[NG] = {0, 1};
#endif
#define GROUP_OF(f) FN(group_f)[f]      /* the order is its own inverse */

/* A box as the mapping pass leaves it, in input order. */
typedef struct RAW {
	double lo[DIM], hi[DIM];
} RAW;

/* One axis of a box's mapping: its coordinates, its cell in the key, its
 * migration bit, and whether it crosses more than one cell face. */
static inline uint64_t FN(map_axis)(const dem_boxes_t *b, const grid_t *g,
				    int d, size_t i, RAW *r, uint64_t key,
				    uint32_t *f, uint32_t *far)
{
	double lo = b->lo[d][i], hi = b->hi[d][i];
	uint32_t c = cell_of(g, d, lo), h = cell_of(g, d, hi);

	r->lo[d] = lo;
	r->hi[d] = hi;
	*f |= (uint32_t)(h != c) << d;
	*far |= h - c > 1;
	return key * g->n[d] + c;
}

/* Map each box to its cell (Box 2.1) in one sequential pass over the
 * caller's arrays: the box's coordinates side by side, and its sort key,
 * packed (pk) or not (wk).  Returns 1 when no box crosses more than one cell
 * face along any axis (the near sweep applies), else 0. */
static int FN(map)(const dem_boxes_t *b, const grid_t *g, RAW *raw,
		   uint64_t *pk, keyed_t *wk)
{
	uint32_t far = 0;

	for (size_t i = 0; i < b->n; i++) {
		uint64_t key = 0;
		uint32_t f = 0;
		/* the axes written out, z (slowest) first */
#if DIM > 2
		key = FN(map_axis)(b, g, 2, i, &raw[i], key, &f, &far);
#endif
#if DIM > 1
		key = FN(map_axis)(b, g, 1, i, &raw[i], key, &f, &far);
#endif
		key = FN(map_axis)(b, g, 0, i, &raw[i], key, &f, &far);
		uint64_t sk = key << DIM | GROUP_OF(f);
		if (pk)
			pk[i] = sk << 32 | i;
		else
			wk[i] = (keyed_t){sk, (uint32_t)i};
	}
	return !far;
}

#ifndef GATHER_AHEAD
#define GATHER_AHEAD 16
#endif

/* Fetch the boxes in cell order; the migration bits come back from the
 * group in the sort key. */
static void FN(gather)(const RAW *raw, const sorted_t *s, size_t n, ENT *ent)
{
	for (size_t k = 0; k < n; k++) {
		uint32_t i = sorted_idx(s, k);
		ENT *r = &ent[k];
		/* the boxes come in random order: ask for one a little ahead
		 * so that its cache miss overlaps this work */
#if GATHER_AHEAD > 0
		if (k + GATHER_AHEAD < n)
			__builtin_prefetch(&raw[sorted_idx(s, k + GATHER_AHEAD)]);
#endif
		for (int d = 0; d < DIM; d++) {
			r->lo[d] = raw[i].lo[d];
			r->hi[d] = raw[i].hi[d];
		}
		r->id = i;
		r->f = FN(group_f)[sorted_key(s, k) & (NG - 1)];
	}
}

/* The non-empty cells of the near sweep: key[j] is the linear index of
 * cell j, s[j * NG + g] where its boxes of group g begin in the sorted
 * array (a group ends where the next begins, the last where cell j + 1
 * begins).  The list ends with a sentinel cell, key UINT64_MAX, at n. */
typedef struct CELLS {
	const uint64_t *key;
	const uint32_t *s;
} CELLS;

/* The slots s[] needed for n boxes. */
#define CELL_SLOTS(n) (((n) + 3) * NG)

/* Build the cell list from the sorted keys; returns the number of
 * non-empty cells.  Branch-free: box k, in slot j * NG + g (cell j, group
 * g), writes k into the 2 NG slots after the previous box's slot; that
 * covers every slot up to its own (no two consecutive boxes are further
 * apart), and the next box overwrites those beyond it.  So each slot ends
 * up holding the first box at or after it. */
static size_t FN(build_cells)(const sorted_t *st, size_t n, uint64_t *key,
			      uint32_t *s)
{
	size_t j = (size_t)-1, p = (size_t)-1;  /* wrap to 0 below */
	uint64_t prev = UINT64_MAX;

	for (size_t k = 0; k < n; k++) {
		uint64_t sk = sorted_key(st, k), c = sk >> DIM;
		j += c != prev;
		prev = c;
		key[j] = c;
		for (size_t t = 1; t <= 2 * NG; t++)
			s[p + t] = (uint32_t)k;
		p = j * NG + (sk & (NG - 1));
	}
	size_t nc = j + 1;
	for (size_t t = p + 1; t < (nc + 1) * NG; t++)
		s[t] = (uint32_t)n;
	key[nc] = UINT64_MAX;
	return nc;
}

/* Room for all the tests of a cell is made at once, unless they are more
 * than this: then row by row, so room stays bounded by a row whatever a
 * cell holds (a crowded cell of boxes that mostly miss one another). */
#define ROOM_MAX 65536

#define SW(name) FN(name)
#include "detect/dcell_sweep.h"
#undef SW
#if DIM == 3 && DCELL_X86_AVX2
#pragma GCC push_options
#pragma GCC target("avx2")
#define DCELL_AVX2 1
#define SW(name) CAT(FN(name), _avx2)
#include "detect/dcell_sweep.h"
#undef SW
#undef DCELL_AVX2
#pragma GCC pop_options
#endif

/* ---- The list sweep of Box 2.1, for sets with long boxes ---- */

/* Cells of the lower and upper corner of a box in cell order. */
typedef struct CH {
	uint32_t c[DIM], hc[DIM];
} CH;

typedef struct CTX {
	const ENT *e;
	const CH *ch;
	item_t *buf[DIM][2];    /* per level: the current list, the migrants */
	dem_pairs_t *out;
	size_t checks;
} CTX;

/* Test every pair of the cell list that no axis forbids (disjoint migrated
 * bits, Fig. 2.8); the test itself branch-free, as in row. */
static void FN(check_cell)(CTX *x, const item_t *cs, size_t ns)
{
	const ENT *e = x->e;
	dem_pairs_t *out = x->out;
	size_t checks = 0;

	for (size_t a = 0; a + 1 < ns; a++) {
		if (!room(out, ns - a - 1))
			return;
		dem_pair_t *w = out->p + out->n;
		const ENT *p = &e[cs[a].e];
		uint32_t ma = cs[a].m;
		for (size_t b = a + 1; b < ns; b++) {
			if (ma & cs[b].m)
				continue;
			const ENT *q = &e[cs[b].e];
			checks++;
			*w = (dem_pair_t){p->id, q->id};
			w += FN(overlap)(p, q, AX_ANY, AX_ANY);
		}
		out->n = (size_t)(w - out->p);
	}
	x->checks += checks;
}

/* Along x: cells in order; boxes reaching past a cell's upper face are
 * carried into the following cells (types 01 and 11). */
static void FN(sweep_x)(CTX *x, const item_t *L, size_t n)
{
	item_t *mig = x->buf[0][0], *cur = x->buf[0][1];
	size_t nm = 0;
	const CH *ch = x->ch;

	for (size_t i = 0; i < n;) {
		uint32_t k = ch[L[i].e].c[0];
		size_t ns = 0;
		uint32_t all = ~0u;
		while (i < n && ch[L[i].e].c[0] == k) {
			all &= L[i].m;
			cur[ns++] = L[i++];
		}
		for (size_t a = 0; a < nm; a++)
			if (ch[mig[a].e].hc[0] >= k) {
				cur[ns] = (item_t){mig[a].e, mig[a].m | 1u};
				all &= cur[ns++].m;
			}
		if (!all)
			FN(check_cell)(x, cur, ns);
		item_t *t = mig;
		mig = cur;
		cur = t;
		nm = ns;
	}
}

#if DIM > 1
/* Does entry a come before entry b in the order of the axes below d? */
static inline int FN(before)(const CH *a, const CH *b, int d)
{
	for (int k = d - 1; k >= 0; k--)
		if (a->c[k] != b->c[k])
			return a->c[k] < b->c[k];
	return 0;
}

/* Along axis d >= 1: slabs (rows in 2D) in order.  The boxes of a slab are
 * merged, in the order of the lower axes, with the boxes migrating from the
 * slabs before (bit d set), and the merged list is swept along d - 1. */
static void FN(sweep)(CTX *x, int d, const item_t *L, size_t n)
{
	if (d == 0) {
		FN(sweep_x)(x, L, n);
		return;
	}
	item_t *mig = x->buf[d][0], *cur = x->buf[d][1];
	size_t nm = 0;
	const CH *ch = x->ch;
	const uint32_t bit = 1u << d;

	for (size_t i = 0; i < n;) {
		uint32_t k = ch[L[i].e].c[d];
		size_t j = i;
		while (j < n && ch[L[j].e].c[d] == k)
			j++;
		size_t ns = 0, a = 0;
		uint32_t all = ~0u;
		for (;;) {
			while (a < nm && ch[mig[a].e].hc[d] < k)
				a++;    /* does not reach this slab */
			int take_mig;
			if (a < nm && i < j)
				take_mig = !FN(before)(&ch[L[i].e], &ch[mig[a].e], d);
			else if (a < nm)
				take_mig = 1;
			else if (i < j)
				take_mig = 0;
			else
				break;
			if (take_mig)
				cur[ns] = (item_t){mig[a].e, mig[a].m | bit}, a++;
			else
				cur[ns] = L[i++];
			all &= cur[ns++].m;
		}
		if (ns > 1 && !all)
			FN(sweep)(x, d - 1, cur, ns);
		item_t *t = mig;
		mig = cur;
		cur = t;
		nm = ns;
	}
}
#endif

/* The list sweep over the boxes in cell order: their cells into ch, the
 * top list (every box, no bit set) into top, the lists of each level from
 * the workspace. */
static int FN(sweep_lists)(const grid_t *g, const ENT *ent, size_t n,
			   CH *ch, item_t *top, dem_detect_ws_t *ws,
			   dem_pairs_t *out, size_t *checks)
{
	item_t *lists = dem_detect_ws_get(ws, WS_LIST,
					  2 * DIM * n * sizeof *lists);
	if (!lists)
		return DEM_EIO;
	for (size_t k = 0; k < n; k++) {
		for (int d = 0; d < DIM; d++) {
			ch[k].c[d] = cell_of(g, d, ent[k].lo[d]);
			ch[k].hc[d] = cell_of(g, d, ent[k].hi[d]);
		}
		top[k] = (item_t){(uint32_t)k, 0};
	}
	CTX x = {.e = ent, .ch = ch, .out = out};
	for (int d = 0; d < DIM; d++) {
		x.buf[d][0] = lists + (2 * d) * n;
		x.buf[d][1] = lists + (2 * d + 1) * n;
	}
#if DIM > 1
	FN(sweep)(&x, DIM - 1, top, n);
#else
	FN(sweep_x)(&x, top, n);
#endif
	*checks += x.checks;
	return DEM_OK;
}

static int FN(dcell_run)(const dem_boxes_t *b, const grid_t *g,
			 dem_detect_ws_t *ws, dem_pairs_t *out,
			 dem_detect_stats_t *st)
{
	size_t n = b->n, checks = 0, n0 = out->n;
	int packed = g->kb <= 32;
	int passes = sort_passes(g->kb);
	size_t ksz = n * (packed ? sizeof(uint64_t) : sizeof(keyed_t));
	/* WS_RAW later holds the cell slots or the cell coordinates */
	size_t rsz = n * sizeof(RAW);
	if (rsz < CELL_SLOTS(n) * sizeof(uint32_t))
		rsz = CELL_SLOTS(n) * sizeof(uint32_t);
	if (rsz < n * sizeof(CH))
		rsz = n * sizeof(CH);
	RAW *raw = dem_detect_ws_get(ws, WS_RAW, rsz);
	ENT *ent = dem_detect_ws_get(ws, WS_ENT, n * sizeof *ent);
	void *key = dem_detect_ws_get(ws, WS_KEY, ksz);
	/* only the first entries, one per non-empty cell, are touched */
	uint64_t *ckey = dem_detect_ws_get(ws, WS_CELL, (n + 1) * sizeof *ckey);
	if (!raw || !ent || !key || !ckey)
		return DEM_EIO;
	/* The radix sort's other buffer is the box array, still unused: the
	 * keys start in the one that makes them end in WS_KEY. */
	static_assert(sizeof(ENT) >= sizeof(keyed_t), "room for the keys");
	void *k0 = passes % 2 ? (void *)ent : key;
	void *k1 = passes % 2 ? key : (void *)ent;

	int near = FN(map)(b, g, raw, packed ? k0 : NULL, packed ? NULL : k0);
	sorted_t s = {NULL, NULL};
	if (packed)
		s.pk = sort_packed(k0, k1, n, g->kb);
	else
		s.wk = sort_wide(k0, k1, n, g->kb);
	FN(gather)(raw, &s, n, ent);
	if (near) {
		uint32_t *slots = (uint32_t *)(void *)raw;
		size_t nc = FN(build_cells)(&s, n, ckey, slots);
		CELLS cl = {ckey, slots};
#if DIM == 3 && DCELL_X86_AVX2
		if (have_avx2())
			checks = CAT(FN(sweep_near), _avx2)(ent, &cl, nc, g, out);
		else
#endif
			checks = FN(sweep_near)(ent, &cl, nc, g, out);
	} else {
		/* cells in WS_RAW, the top list in WS_KEY: both done with */
		static_assert(sizeof(item_t) <= sizeof(uint64_t), "room");
		if (FN(sweep_lists)(g, ent, n, (CH *)(void *)raw, key, ws, out,
				    &checks) != DEM_OK)
			return DEM_EIO;
	}
	pairs_order(out, n0);
	if (st)
		st->checks += checks;
	return out->nomem ? DEM_EIO : DEM_OK;
}

#undef CAT_
#undef CAT
#undef ENT
#undef CH
#undef CTX
#undef RAW
#undef CELLS
#undef CELL_SLOTS
#undef GROUP_OF
#undef ROOM_MAX
#undef NG
#undef FN
