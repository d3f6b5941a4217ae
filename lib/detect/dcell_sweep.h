/* dcell_sweep.h - the near sweep of the D-cell (see dcell.c), included by
 * dcell_impl.h once per dimension with SW(name) naming its functions, and
 * for DIM 3 on x86-64 a second time under the AVX2 target with DCELL_AVX2
 * defined: then the box test of row() takes the three axes at once, and
 * dcell_run picks that sweep when the processor has AVX2. */

/* The overlap test of closed boxes p and q along axis d, branch-free.  How
 * depends on where the cell of q lies from that of p along d: when beyond
 * it (AX_ABOVE), lo(q) > lo(p) (cell_of is monotone), so the boxes overlap
 * along d just when lo(q) <= hi(p); when before it (AX_BELOW), just when
 * lo(p) <= hi(q); else (AX_ANY) when the larger lower bound is not above the
 * smaller upper bound. */
static inline int SW(axis_ok)(const ENT *p, const ENT *q, int d, int where)
{
	if (where == AX_ABOVE)
		return q->lo[d] <= p->hi[d];
	if (where == AX_BELOW)
		return p->lo[d] <= q->hi[d];
	return (p->lo[d] > q->lo[d] ? p->lo[d] : q->lo[d]) <=
	       (p->hi[d] < q->hi[d] ? p->hi[d] : q->hi[d]);
}

/* The overlap test of closed boxes p and q, q's cell lying along y and z as
 * wy and wz say.  The axes are written out: the compiler does not unroll a
 * loop over them. */
static inline int SW(overlap)(const ENT *p, const ENT *q, int wy, int wz)
{
	(void)wy;
	(void)wz;
#if DIM == 1
	return SW(axis_ok)(p, q, 0, AX_ANY);
#elif DIM == 2
	return SW(axis_ok)(p, q, 0, AX_ANY) & SW(axis_ok)(p, q, 1, wy);
#else
	return SW(axis_ok)(p, q, 0, AX_ANY) & SW(axis_ok)(p, q, 1, wy) &
	       SW(axis_ok)(p, q, 2, wz);
#endif
}

/* Test box p against the boxes j .. j1 - 1, whose cells lie along y and z
 * as wy and wz say.  The pair is always written and kept only when the
 * boxes overlap, so the test is branch-free. */
#ifdef DCELL_AVX2
/* The same with the three axes at once (AVX2, DIM 3): lanes 0-2 test
 * lo(q) <= hi(p), lanes 1-3 of the second load hi(q) >= lo(p); the
 * fourth lane of each is a comparison with an infinity that holds.  The
 * full closed-box test, so wy and wz (what the scalar test saves on) are
 * not needed; the same pairs. */
static inline dem_pair_t *SW(row)(const ENT *e, const ENT *p, size_t j,
				   size_t j1, dem_pair_t *w, int wy, int wz)
{
	(void)wy;
	(void)wz;
	const __m256d ph = _mm256_setr_pd(p->hi[0], p->hi[1], p->hi[2], INFINITY);
	const __m256d pl = _mm256_setr_pd(-INFINITY, p->lo[0], p->lo[1], p->lo[2]);
	for (; j < j1; j++) {
		const ENT *q = &e[j];
		__m256d a = _mm256_loadu_pd(&q->lo[0]);  /* lo0 lo1 lo2 hi0 */
		__m256d b = _mm256_loadu_pd(&q->lo[2]);  /* lo2 hi0 hi1 hi2 */
		__m256d m = _mm256_and_pd(_mm256_cmp_pd(a, ph, _CMP_LE_OQ),
					  _mm256_cmp_pd(b, pl, _CMP_GE_OQ));
		*w = (dem_pair_t){p->id, q->id};
		w += _mm256_movemask_pd(m) == 0xF;
	}
	return w;
}
#else
static inline dem_pair_t *SW(row)(const ENT *e, const ENT *p, size_t j,
				   size_t j1, dem_pair_t *w, int wy, int wz)
{
	for (; j < j1; j++) {
		const ENT *q = &e[j];
		*w = (dem_pair_t){p->id, q->id};
		w += SW(overlap)(p, q, wy, wz);
	}
	return w;
}
#endif

/* The rows of the boxes of A in the runs r (as[]: A's group starts) against
 * the span t of a row of neighbours lying along y and z as wy and wz say,
 * writing at w (room made already, or row by row when chunked); adds the
 * tests to *checks.  Returns where the next pair goes, NULL without
 * memory. */
static inline dem_pair_t *SW(rows)(const ENT *e, const uint32_t *as,
				    const runs_t *r, const span_t *t,
				    dem_pair_t *w, int chunked,
				    dem_pairs_t *out, size_t *checks,
				    int wy, int wz)
{
	for (int q = 0; q < r->n; q++)
		for (uint32_t i = as[r->b[q]]; i < as[r->e[q]]; i++) {
			uint32_t end = e[i].f & 1 ? t->e1 : t->e0;
			if (chunked) {
				out->n = (size_t)(w - out->p);
				if (!room(out, end - t->s))
					return NULL;
				w = out->p + out->n;
			}
			*checks += end - t->s;
			w = SW(row)(e, &e[i], t->s, end, w, wy, wz);
		}
	return w;
}

/* The near sweep (see dcell.c).  For every non-empty cell A in order, the
 * tests of a box of A are at most one row of boxes per row of neighbour
 * cells:
 * 1. the boxes after it in A (type 00 against 00 in A) and, when it reaches
 *    the next cell B = A + (1, 0, 0), all of B (its 01 against B's 00);
 * 2. per row of neighbours A + (vx, vy, vz), vx = -1 .. 1 (nrow_t, found by
 *    its cursor), when the box reaches the row along y and z: the boxes of
 *    A + (-1, vy, vz) that reach it along x (and y if vy = -1), a suffix of
 *    that cell, then all of A + (0, vy, vz) and, when the box reaches the
 *    next cell along x, all of A + (1, vy, vz).
 * These are the pairs of types da and db (da & db = 0) of the owner cell T
 * of Fig. 2.8: 00 against 01, 10 and 11 when one of them is 0, 01 against
 * 10 otherwise (T itself may be empty then).  Taking the last two cells of
 * a row whole lets the row run on unbroken; their boxes that do not reach
 * T are tested in vain, as they cannot overlap the box.  Every pair of
 * neighbour cells is met once, from the one with the smaller index, and
 * every pair of boxes in it once, so no pair is reported twice. */
static size_t SW(sweep_near)(const ENT *e, const CELLS *cl, size_t nc,
			     const grid_t *g, dem_pairs_t *out)
{
	runs_t runs[NG];
	nrow_t rows[NROW_MAX];
	span_t sp[NROW_MAX];
	size_t cur[NROW_MAX] = {0}, checks = 0;
	int nrow = nrow_setup(g, DIM, rows);

	runs_setup(runs, FN(group_f), NG);
	for (size_t a = 0; a < nc; a++) {
		uint64_t akey = cl->key[a];
		const uint32_t *as = &cl->s[a * NG];    /* as[NG]: A's end */
		/* A's place in the grid: which neighbours exist */
		uint64_t cx = akey % g->n[0], cyz = akey / g->n[0];
		uint64_t cy = DIM > 1 ? cyz % g->n[1] : 0;
		uint64_t cz = DIM > 2 ? cyz / g->n[1] : 0;
		int xlo = cx > 0, xhi = cx + 1 < g->n[0];
		/* 1: the cell itself and the next one along x, which ends at
		 * xend (A's own end when there is none) */
		uint32_t xend = xhi && cl->key[a + 1] == akey + 1 ?
				cl->s[(a + 2) * NG] : as[NG];
		size_t total = (size_t)(as[NG] - as[0]) * (xend - as[0]);
		/* 2: the rows of neighbours inside the grid */
		int ns = 0;
		for (int k = 0; k < nrow; k++) {
			const nrow_t *rk = &rows[k];
			if ((rk->vy < 0 && cy == 0) ||
			    (rk->vy > 0 && cy + 1 >= g->n[1]) ||
			    (rk->vz > 0 && cz + 1 >= g->n[2]))
				continue;
			/* none of A's boxes reaches the row: nothing to find
			 * (the cursor catches up later) */
			const runs_t *r = &runs[rk->da];
			size_t ni = 0;
			for (int q = 0; q < r->n; q++)
				ni += as[r->e[q]] - as[r->b[q]];
			if (ni == 0)
				continue;
			uint64_t mid = akey + rk->delta;
			while (cl->key[cur[k]] < mid - xlo)
				cur[k]++;
			size_t b = cur[k];
			span_t t = {0, 0, 0, rk};
			if (xlo && cl->key[b] == mid - 1) {
				/* those reaching x (and y): a suffix, see
				 * group_f */
				t.s = cl->s[b * NG + runs[rk->db | 1].b[0]];
				t.e0 = cl->s[++b * NG];
			} else {
				t.s = t.e0 = cl->s[b * NG];
			}
			if (cl->key[b] == mid)
				t.e0 = cl->s[++b * NG];
			t.e1 = xhi && cl->key[b] == mid + 1 ?
			       cl->s[(b + 1) * NG] : t.e0;
			if (t.s == t.e1)
				continue;
			total += ni * (t.e1 - t.s);
			sp[ns++] = t;
		}

		int chunked = total > ROOM_MAX;
		if (!chunked && !room(out, total))
			return checks;
		dem_pair_t *w = out->p + out->n;
		for (uint32_t i = as[0]; i < as[NG]; i++) {
			uint32_t end = e[i].f & 1 ? xend : as[NG];
			if (chunked) {
				out->n = (size_t)(w - out->p);
				if (!room(out, end - i))
					return checks;
				w = out->p + out->n;
			}
			checks += end - i - 1;
			w = SW(row)(e, &e[i], i + 1, end, w, AX_ANY, AX_ANY);
		}
		/* each kind of row written out, so that each gets its own
		 * test: the row lies beyond A along z when vz = 1, and
		 * along y as vy says */
		for (int k = 0; k < ns && w; k++) {
			const runs_t *r = &runs[sp[k].row->da];
			int vy = sp[k].row->vy, vz = sp[k].row->vz;
			if (vz == 0)
				w = SW(rows)(e, as, r, &sp[k], w, chunked, out,
					     &checks, AX_ABOVE, AX_ANY);
			else if (vy < 0)
				w = SW(rows)(e, as, r, &sp[k], w, chunked, out,
					     &checks, AX_BELOW, AX_ABOVE);
			else if (vy == 0)
				w = SW(rows)(e, as, r, &sp[k], w, chunked, out,
					     &checks, AX_ANY, AX_ABOVE);
			else
				w = SW(rows)(e, as, r, &sp[k], w, chunked, out,
					     &checks, AX_ABOVE, AX_ABOVE);
		}
		if (!w)
			return checks;
		out->n = (size_t)(w - out->p);
	}
	return checks;
}

