/* dcell_impl.h - the D-cell mapping and sweeps for one dimension DIM;
 * included by dcell.c once per dimension, so the inner loops have constant
 * trip counts. */
#define CAT_(a, b) a##b
#define CAT(a, b) CAT_(a, b)
#define ENT CAT(ent, DIM)
#define CH CAT(ch, DIM)
#define CTX CAT(ctx, DIM)
#define CELL CAT(cell, DIM)
#define FN(name) CAT(name, DIM)

/* A box in cell order, all the tests need in one place. */
typedef struct ENT {
	double lo[DIM], hi[DIM];
	uint32_t id;            /* index in the caller's box set */
	uint32_t f;             /* bit d: the box reaches past its cell along d */
} ENT;

/* Within a cell the boxes are sorted into groups by their migration bits
 * f, in this order (group -> f): the boxes that reach the next cell along x,
 * along y, or along both are then one run each, the inner loop of the near
 * sweep's tests; any other set is at most three runs.  In 2D and 1D it is
 * the same order without the groups that have a z bit. */
#define NG (1 << DIM)
#if DIM == 3
static const unsigned char FN(group_f)[NG] = {0, 4, 1, 5, 7, 3, 6, 2};
static const unsigned char FN(group_of)[NG] = {0, 2, 7, 5, 1, 3, 6, 4};
#elif DIM == 2
static const unsigned char FN(group_f)[NG] = {0, 1, 3, 2};
static const unsigned char FN(group_of)[NG] = {0, 1, 3, 2};
#else
static const unsigned char FN(group_f)[NG] = {0, 1};
static const unsigned char FN(group_of)[NG] = {0, 1};
#endif

/* Map each box to its cell (Box 2.1) in one sequential pass over the
 * caller's arrays: the box as an ENT, in input order, and its sort key.
 * Returns 1 when no box crosses more than one cell face along any axis (the
 * near sweep applies), else 0. */
static int FN(map)(const dem_boxes_t *b, const grid_t *g, ENT *raw,
		   uint64_t *pk, keyed_t *wk)
{
	uint32_t far = 0;

	for (size_t i = 0; i < b->n; i++) {
		ENT *r = &raw[i];
		uint64_t key = 0;
		uint32_t f = 0;
		for (int d = DIM - 1; d >= 0; d--) {
			double lo = b->lo[d][i], hi = b->hi[d][i];
			uint32_t c = cell_of(g, d, lo), h = cell_of(g, d, hi);
			r->lo[d] = lo;
			r->hi[d] = hi;
			f |= (uint32_t)(h != c) << d;
			far |= h - c > 1;
			key = key * g->n[d] + c;
		}
		r->id = (uint32_t)i;
		r->f = f;
		uint64_t sk = key << DIM | FN(group_of)[f];
		if (pk)
			pk[i] = sk << 32 | i;
		else
			wk[i] = (keyed_t){sk, (uint32_t)i};
	}
	return !far;
}

/* A non-empty cell of the near sweep: its linear index and where the boxes
 * of each group begin in the sorted array; the last group ends where the
 * next cell begins.  The table ends with a sentinel (key UINT64_MAX). */
typedef struct CELL {
	uint64_t key;
	uint32_t s[NG];
} CELL;

/* One pass over the sorted keys; returns the number of non-empty cells. */
static size_t FN(build_cells)(const sorted_t *s, size_t n, CELL *cl)
{
	size_t nc = 0;
	uint64_t cur = UINT64_MAX;
	unsigned fill = NG - 1; /* s[0 .. fill] of the last cell are set */

	for (size_t k = 0; k < n; k++) {
		uint64_t sk = sorted_key(s, k);
		unsigned g = (unsigned)(sk & (NG - 1));
		if (sk >> DIM != cur) {
			while (fill < NG - 1)
				cl[nc - 1].s[++fill] = (uint32_t)k;
			cur = sk >> DIM;
			cl[nc].key = cur;
			cl[nc++].s[0] = (uint32_t)k;
			fill = 0;
		}
		while (fill < g)
			cl[nc - 1].s[++fill] = (uint32_t)k;
	}
	while (fill < NG - 1)
		cl[nc - 1].s[++fill] = (uint32_t)n;
	cl[nc].key = UINT64_MAX;
	for (int g = 0; g < NG; g++)
		cl[nc].s[g] = (uint32_t)n;
	return nc;
}

/* The overlap test of closed boxes p and q, branch-free: along every axis
 * the larger lower bound is not above the smaller upper bound.  The axes
 * are written out: the compiler does not unroll a loop over them. */
#define AXIS_OK(d) ((p->lo[d] > q->lo[d] ? p->lo[d] : q->lo[d]) <= \
		    (p->hi[d] < q->hi[d] ? p->hi[d] : q->hi[d]))
static inline int FN(overlap)(const ENT *p, const ENT *q)
{
#if DIM == 1
	return AXIS_OK(0);
#elif DIM == 2
	return AXIS_OK(0) & AXIS_OK(1);
#else
	return AXIS_OK(0) & AXIS_OK(1) & AXIS_OK(2);
#endif
}
#undef AXIS_OK

/* Products of more tests than this make room row by row, so room stays
 * bounded by a row whatever the cell holds. */
#define ROOM_MAX 65536

/* Test every box of the runs ra (groups of cell A, as[] its group starts)
 * against the boxes j0 .. j1 - 1; tri: against the boxes after it only
 * (the cell with itself, j1 its end).  The pair is always written and kept
 * only when the boxes overlap, so the test itself is branch-free.  Returns
 * the number of tests. */
static size_t FN(product)(const ENT *e, const uint32_t *as, const runs_t *ra,
			  size_t j0, size_t j1, int tri, dem_pairs_t *out)
{
	size_t ni = 0, total;

	for (int r = 0; r < ra->n; r++)
		ni += as[ra->e[r]] - as[ra->b[r]];
	total = tri ? ni * (ni - 1) / 2 : ni * (j1 - j0);
	if (total == 0)
		return 0;
#ifdef DCELL_COUNT
	dc_prod++;
	dc_rows += ni;
#endif
	int chunked = total > ROOM_MAX;
	if (!chunked && !room(out, total))
		return 0;
	dem_pair_t *w = out->p + out->n;
	for (int r = 0; r < ra->n; r++)
		for (size_t i = as[ra->b[r]]; i < as[ra->e[r]]; i++) {
			const ENT *p = &e[i];
			size_t j = tri ? i + 1 : j0;
			if (chunked) {
				out->n = (size_t)(w - out->p);
				if (!room(out, j1 - j))
					return 0;
				w = out->p + out->n;
			}
			for (; j < j1; j++) {
				const ENT *q = &e[j];
				*w = (dem_pair_t){p->id, q->id};
				w += FN(overlap)(p, q);
			}
		}
	out->n = (size_t)(w - out->p);
	return total;
}

/* The near sweep (see dcell.c): every non-empty cell A in order, with
 * 1. the boxes of A among themselves (type 00 against 00 in A);
 * 2. the next cell along x, B = A + (1, 0, 0): A's boxes of type 01 in the
 *    owner cell B against B's 00;
 * 3. the rows of neighbours (nrow_t), each found by its cursor.
 * In the owner cell T the boxes of A are of type da, those of B of type db,
 * da & db = 0: Fig. 2.8's 00 against 01, 10 and 11 when one of them is 0,
 * and 01 against 10 otherwise (T itself may be empty then). */
static size_t FN(sweep_near)(const ENT *e, const CELL *cl, size_t nc,
			     const grid_t *g, dem_pairs_t *out)
{
	runs_t runs[NG];
	nrow_t rows[NROW_MAX];
	size_t cur[NROW_MAX] = {0}, checks = 0;
	int nrow = nrow_setup(g, DIM, rows);
	int wide = g->n[0] > 1;         /* neighbours along x exist */

	runs_setup(runs, FN(group_f), NG);
	for (size_t a = 0; a < nc && !out->nomem; a++) {
		const CELL *A = &cl[a];
		uint32_t as[NG + 1], bs[NG + 1];
		for (int k = 0; k < NG; k++)
			as[k] = A->s[k];
		as[NG] = A[1].s[0];
		checks += FN(product)(e, as, &runs[0], as[0], as[NG], 1, out);
		if (wide && A[1].key == A->key + 1)
			checks += FN(product)(e, as, &runs[1], as[NG], A[2].s[0],
					      0, out);
		for (int k = 0; k < nrow; k++) {
			/* the row's cells A + delta + vx, vx = -1 .. 1 */
			uint64_t mid = A->key + rows[k].delta;
			uint64_t first = wide ? mid - 1 : mid, last = wide ? mid + 1 : mid;
			while (cl[cur[k]].key < first)
				cur[k]++;
			for (size_t c = cur[k]; cl[c].key <= last; c++) {
				const CELL *B = &cl[c];
				unsigned da = rows[k].da, db = rows[k].db;
				if (B->key < mid)
					db |= 1;        /* vx = -1 */
				else if (B->key > mid)
					da |= 1;        /* vx = +1 */
				for (int m = 0; m < NG; m++)
					bs[m] = B->s[m];
				bs[NG] = B[1].s[0];
				/* one run: see group_f */
				const runs_t *rb = &runs[db];
				checks += FN(product)(e, as, &runs[da], bs[rb->b[0]],
						      bs[rb->e[0]], 0, out);
			}
		}
	}
	return checks;
}

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
 * bits, Fig. 2.8), branch-free as in product. */
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
			w += FN(overlap)(p, q);
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

static int FN(sweep_lists)(const grid_t *g, const ENT *ent, size_t n,
			   CH *ch, dem_detect_ws_t *ws, dem_pairs_t *out,
			   size_t *checks)
{
	item_t *top = dem_detect_ws_get(ws, WS_LIST,
					(2 * DIM + 1) * n * sizeof *top);
	if (!top)
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
		x.buf[d][0] = top + (2 * d + 1) * n;
		x.buf[d][1] = top + (2 * d + 2) * n;
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
	size_t ksz = n * (packed ? sizeof(uint64_t) : sizeof(keyed_t));
	/* WS_RAW later holds the cell table or the cell coordinates */
	size_t rsz = n * sizeof(ENT);
	if (rsz < (n + 1) * sizeof(CELL))
		rsz = (n + 1) * sizeof(CELL);
	ENT *raw = dem_detect_ws_get(ws, WS_RAW, rsz);
	ENT *ent = dem_detect_ws_get(ws, WS_ENT, n * sizeof *ent);
	void *key = dem_detect_ws_get(ws, WS_KEY, ksz);
	void *tmp = dem_detect_ws_get(ws, WS_TMP, ksz);
	if (!raw || !ent || !key || !tmp)
		return DEM_EIO;

	TT(0);
	int near = FN(map)(b, g, raw, packed ? key : NULL, packed ? NULL : key);
	TT(1);
	sorted_t s = {NULL, NULL};
	if (packed)
		s.pk = sort_packed(key, tmp, n, g->kb);
	else
		s.wk = sort_wide(key, tmp, n, g->kb);
	TT(2);
	for (size_t k = 0; k < n; k++)
		ent[k] = raw[sorted_idx(&s, k)];
	TT(3);
	if (near) {
		CELL *cl = (CELL *)(void *)raw;
		size_t nc = FN(build_cells)(&s, n, cl);
		TT(4);
		checks = FN(sweep_near)(ent, cl, nc, g, out);
	} else {
		TT(4);
		if (FN(sweep_lists)(g, ent, n, (CH *)(void *)raw, ws, out,
				    &checks) != DEM_OK)
			return DEM_EIO;
	}
	pairs_order(out, n0);
	TT(5);
	if (st)
		st->checks += checks;
	return out->nomem ? DEM_EIO : DEM_OK;
}

#undef CAT_
#undef CAT
#undef ENT
#undef CH
#undef CTX
#undef CELL
#undef NG
#undef FN
