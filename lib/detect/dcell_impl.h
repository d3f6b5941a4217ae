/* dcell_impl.h - the D-cell sweep for one dimension DIM; included by dcell.c
 * once per dimension, so the inner loops have constant trip counts. */
#define CAT_(a, b) a##b
#define CAT(a, b) CAT_(a, b)
#define ENT CAT(ent, DIM)
#define CTX CAT(ctx, DIM)
#define FN(name) CAT(name, DIM)

/* A box in cell order, with what the sweep needs next to each other. */
typedef struct ENT {
	double lo[DIM], hi[DIM];
	uint32_t c[DIM];        /* cell of the lower corner */
	uint32_t hc[DIM];       /* cell of the upper corner */
	uint32_t id;            /* index in the caller's box set */
} ENT;

typedef struct CTX {
	const ENT *e;
	item_t *buf[DIM][2];    /* per level: the current list, the migrants */
	dem_pairs_t *out;
	size_t checks;
} CTX;

/* Test every pair of the cell list that no axis forbids (disjoint migrated
 * bits, Fig. 2.8).  Room for every candidate pair is made first, so the
 * test itself is branch-free: the pair is always written and kept only when
 * the boxes overlap. */
static void FN(check_cell)(CTX *x, const item_t *cs, size_t ns)
{
	const ENT *e = x->e;
	dem_pairs_t *out = x->out;
	size_t checks = 0;

	while (out->cap - out->n < ns * (ns - 1) / 2)
		if (dem_pairs_grow(out) != 0)
			return;
	dem_pair_t *w = out->p + out->n;
	for (size_t a = 0; a + 1 < ns; a++) {
		const ENT *p = &e[cs[a].e];
		uint32_t ma = cs[a].m;
		for (size_t b = a + 1; b < ns; b++) {
			if (ma & cs[b].m)
				continue;
			const ENT *q = &e[cs[b].e];
			int hit = 1;
			checks++;
			for (int d = 0; d < DIM; d++)
				hit &= (p->lo[d] <= q->hi[d]) & (q->lo[d] <= p->hi[d]);
			w->i = p->id < q->id ? p->id : q->id;
			w->j = p->id < q->id ? q->id : p->id;
			w += hit;
		}
	}
	out->n = (size_t)(w - out->p);
	x->checks += checks;
}

/* Along x: cells in order; boxes reaching past a cell's upper face are
 * carried into the following cells (types 01 and 11). */
static void FN(sweep_x)(CTX *x, const item_t *L, size_t n)
{
	item_t *mig = x->buf[0][0], *cur = x->buf[0][1];
	size_t nm = 0;
	const ENT *e = x->e;

	for (size_t i = 0; i < n;) {
		uint32_t k = e[L[i].e].c[0];
		size_t ns = 0;
		uint32_t all = ~0u;
		while (i < n && e[L[i].e].c[0] == k) {
			all &= L[i].m;
			cur[ns++] = L[i++];
		}
		for (size_t a = 0; a < nm; a++)
			if (e[mig[a].e].hc[0] >= k) {
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
static inline int FN(before)(const ENT *a, const ENT *b, int d)
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
	const ENT *e = x->e;
	const uint32_t bit = 1u << d;

	for (size_t i = 0; i < n;) {
		uint32_t k = e[L[i].e].c[d];
		size_t j = i;
		while (j < n && e[L[j].e].c[d] == k)
			j++;
		size_t ns = 0, a = 0;
		uint32_t all = ~0u;
		for (;;) {
			while (a < nm && e[mig[a].e].hc[d] < k)
				a++;    /* does not reach this slab */
			int take_mig;
			if (a < nm && i < j)
				take_mig = !FN(before)(&e[L[i].e], &e[mig[a].e], d);
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

static int FN(dcell_run)(const dem_boxes_t *b, const grid_t *g,
			 dem_pairs_t *out, dem_detect_stats_t *st)
{
	size_t n = b->n;
	ENT *raw = malloc(n * sizeof *raw), *ent = NULL;
	keyed_t *ka = malloc(n * sizeof *ka), *kb = malloc(n * sizeof *kb);
	item_t *top = NULL, *bufs = NULL;
	int rc = DEM_EIO;

	if (!raw || !ka || !kb)
		goto done;
	/* Map each box to its cell (sequential pass over the caller's arrays). */
	for (size_t i = 0; i < n; i++) {
		ENT *r = &raw[i];
		uint64_t key = 0;
		for (int d = DIM - 1; d >= 0; d--) {
			r->lo[d] = b->lo[d][i];
			r->hi[d] = b->hi[d][i];
			r->c[d] = cell_of(g, d, r->lo[d]);
			r->hc[d] = cell_of(g, d, r->hi[d]);
			key = key * g->n[d] + r->c[d];
		}
		r->id = (uint32_t)i;
		ka[i] = (keyed_t){key, (uint32_t)i};
	}
	radix_sort(&ka, &kb, n, g->bits);
	free(kb);
	kb = NULL;
	ent = malloc(n * sizeof *ent);
	if (!ent)
		goto done;
	for (size_t i = 0; i < n; i++)
		ent[i] = raw[ka[i].idx];
	free(raw);
	free(ka);
	raw = NULL;
	ka = NULL;

	top = malloc(n * sizeof *top);
	bufs = malloc(2 * DIM * n * sizeof *bufs);
	if (!top || !bufs)
		goto done;
	CTX x = {.e = ent, .out = out};
	for (int d = 0; d < DIM; d++) {
		x.buf[d][0] = bufs + (2 * d) * n;
		x.buf[d][1] = bufs + (2 * d + 1) * n;
	}
	for (size_t i = 0; i < n; i++)
		top[i] = (item_t){(uint32_t)i, 0};
#if DIM > 1
	FN(sweep)(&x, DIM - 1, top, n);
#else
	FN(sweep_x)(&x, top, n);
#endif
	if (st)
		st->checks += x.checks;
	rc = out->nomem ? DEM_EIO : DEM_OK;
done:
	free(raw);
	free(ent);
	free(ka);
	free(kb);
	free(top);
	free(bufs);
	return rc;
}

#undef CAT_
#undef CAT
#undef ENT
#undef CTX
#undef FN
