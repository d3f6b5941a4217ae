/* detect.c - the detection front end: options, cell size rule, periodic
 * images; the shared types are boxes.c's. */
#include "detect/detect.h"

#include "detect/algo.h"
#include "detect/boxes.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const algo_names[] = {
	[DEM_DETECT_DCELL] = "dcell", [DEM_DETECT_NBS] = "nbs",
	[DEM_DETECT_SCELL] = "scell", [DEM_DETECT_ADT] = "adt",
	[DEM_DETECT_ASDT] = "asdt",   [DEM_DETECT_BRUTE] = "brute",
};

void dem_detect_opts_init(dem_detect_opts_t *o)
{
	memset(o, 0, sizeof *o);
	o->algo = DEM_DETECT_DCELL;
}

const char *dem_detect_algo_name(dem_detect_algo_t a)
{
	return (unsigned)a < sizeof algo_names / sizeof *algo_names ?
		algo_names[a] : "?";
}

int dem_detect_algo_parse(const char *name)
{
	for (size_t a = 0; a < sizeof algo_names / sizeof *algo_names; a++)
		if (strcmp(name, algo_names[a]) == 0)
			return (int)a;
	return -1;
}

/* Ch. 2.5 finds the best cell about 3 (2D) or 5 (3D) times the mean object
 * size, and says the optimum has to be found by measurement.  Measured on
 * this implementation (examples/detect-bench, cell-size sweeps), the best
 * factor of the mean box extent is 2.5-4 in 2D, where the thesis's 3 sits,
 * but 1.5-2.5 in 3D, where 5 is three times slower: the defaults are 3 and
 * 2.  Per axis, from the mean box extent along it.  Boxes of zero size
 * give a cell holding about factor boxes on average instead.  One pass per
 * axis with four partial sums, so the additions do not wait on each other;
 * the span of the set is needed (and scanned) only when every box is flat. */
static void resolve_cell(const dem_boxes_t *b, const dem_detect_opts_t *o,
			 double *cell)
{
	double f = o->cell_factor > 0 ? o->cell_factor : b->dim == 3 ? 2 : 3;
	size_t n = b->n;

	for (int d = 0; d < b->dim; d++) {
		if (o->cell[d] > 0) {
			cell[d] = o->cell[d];
			continue;
		}
		const double *lo = b->lo[d], *hi = b->hi[d];
		double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
		size_t i = 0;
		for (; i + 4 <= n; i += 4) {
			s0 += hi[i] - lo[i];
			s1 += hi[i + 1] - lo[i + 1];
			s2 += hi[i + 2] - lo[i + 2];
			s3 += hi[i + 3] - lo[i + 3];
		}
		for (; i < n; i++)
			s0 += hi[i] - lo[i];
		double mean = n ? ((s0 + s1) + (s2 + s3)) / (double)n : 0;
		if (mean > 0) {
			cell[d] = f * mean;
			continue;
		}
		double min = HUGE_VAL, max = -HUGE_VAL;
		for (i = 0; i < n; i++) {
			min = lo[i] < min ? lo[i] : min;
			max = hi[i] > max ? hi[i] : max;
		}
		if (max > min)
			cell[d] = (max - min) *
				  pow(f / (double)n, 1.0 / b->dim);
		else
			cell[d] = 1;
	}
}

static int run(const dem_boxes_t *b, const dem_detect_opts_t *o,
	       dem_pairs_t *out, dem_detect_stats_t *st, dem_error_t *e)
{
	double cell[DEM_MAXDIM] = {0};
	int rc;

	if (o->algo == DEM_DETECT_NBS && b->dim != 2)
		return dem_error_set(e, DEM_EINPUT,
				     "NBS is a 2D method; use dcell for %dD", b->dim);
	resolve_cell(b, o, cell);
	switch (o->algo) {
	case DEM_DETECT_DCELL: rc = dem_detect_dcell_ws(b, cell, o->ws, out, st); break;
	case DEM_DETECT_NBS:   rc = dem_detect_nbs(b, cell, out, st); break;
	case DEM_DETECT_SCELL: rc = dem_detect_scell(b, cell, out, st); break;
	case DEM_DETECT_ADT:   rc = dem_detect_adt(b, out, st); break;
	case DEM_DETECT_ASDT:  rc = dem_detect_asdt(b, out, st); break;
	case DEM_DETECT_BRUTE: rc = dem_detect_brute(b, out, st); break;
	default:
		return dem_error_set(e, DEM_EUSAGE, "unknown detection algorithm");
	}
	if (rc != DEM_OK || out->nomem)
		return dem_error_nomem(e, "contact pairs");
	return DEM_OK;
}

/* Periodic axes by images: every box is wrapped so its lower corner lies in
 * the period, and a box reaching the upper face gets images shifted back by
 * one period on every non-empty subset of the axes it crosses.  A pair of
 * copies stands for a pair of boxes when the copies are not both shifted
 * along any one axis; with boxes shorter than half a period the relative
 * shift per axis is unique, so each pair is then found exactly once. */
static int run_periodic(const dem_boxes_t *b, const dem_detect_opts_t *o,
			dem_pairs_t *out, dem_detect_stats_t *st,
			dem_error_t *e)
{
	double per[DEM_MAXDIM] = {0};
	size_t total = 0;
	int rc;

	for (int d = 0; d < b->dim; d++) {
		if (!(o->periodic >> d & 1))
			continue;
		per[d] = o->period_hi[d] - o->period_lo[d];
		if (!(per[d] > 0) || !isfinite(per[d]))
			return dem_error_set(e, DEM_EINPUT,
					     "periodic axis %c: the period must be positive",
					     "xyz"[d]);
	}
	for (size_t i = 0; i < b->n; i++) {
		unsigned cross = 0;
		for (int d = 0; d < b->dim; d++) {
			if (!per[d])
				continue;
			double w = b->hi[d][i] - b->lo[d][i];
			if (!(w < per[d] / 2))
				return dem_error_set(e, DEM_EINPUT,
						     "object %zu is %g long along %c, not shorter than half the period %g",
						     i, w, "xyz"[d], per[d]);
			double lo = b->lo[d][i] - floor((b->lo[d][i] - o->period_lo[d]) / per[d]) * per[d];
			if (lo + w >= o->period_hi[d])
				cross |= 1u << d;
		}
		total += (size_t)1 << __builtin_popcount(cross);
	}
	if (total > UINT32_MAX)
		return dem_error_set(e, DEM_EINPUT, "too many objects with periodic images");

	dem_boxes_t x;
	uint32_t *owner = malloc(total * sizeof *owner);
	unsigned char *shift = malloc(total);
	if (!owner || !shift || dem_boxes_alloc(&x, b->dim, total) != DEM_OK) {
		free(owner);
		free(shift);
		return dem_error_nomem(e, "periodic images");
	}
	size_t k = 0;
	for (size_t i = 0; i < b->n; i++) {
		double lo[DEM_MAXDIM], hi[DEM_MAXDIM];
		unsigned cross = 0;
		for (int d = 0; d < b->dim; d++) {
			double w = b->hi[d][i] - b->lo[d][i];
			lo[d] = b->lo[d][i];
			if (per[d]) {
				lo[d] -= floor((lo[d] - o->period_lo[d]) / per[d]) * per[d];
				if (lo[d] + w >= o->period_hi[d])
					cross |= 1u << d;
			}
			hi[d] = lo[d] + w;
		}
		/* every subset s of cross, the empty one (the box itself) first */
		unsigned s = 0;
		do {
			for (int d = 0; d < b->dim; d++) {
				double sh = (s >> d & 1) ? per[d] : 0;
				x.lo[d][k] = lo[d] - sh;
				x.hi[d][k] = hi[d] - sh;
			}
			owner[k] = (uint32_t)i;
			shift[k++] = (unsigned char)s;
			s = (s - cross) & cross;
		} while (s);
	}
	if (st)
		st->ghosts = total - b->n;

	dem_pairs_t raw;
	dem_pairs_init(&raw);
	rc = run(&x, o, &raw, st, e);
	if (rc == DEM_OK) {
		for (size_t p = 0; p < raw.n; p++) {
			uint32_t a = raw.p[p].i, c = raw.p[p].j;
			if ((shift[a] & shift[c]) == 0 && owner[a] != owner[c])
				dem_pairs_push(out, owner[a], owner[c]);
		}
		if (out->nomem)
			rc = dem_error_nomem(e, "contact pairs");
	}
	dem_pairs_free(&raw);
	dem_boxes_free(&x);
	free(owner);
	free(shift);
	return rc;
}

int dem_detect(const dem_boxes_t *b, const dem_detect_opts_t *o,
	       dem_pairs_t *out, dem_detect_stats_t *st, dem_error_t *e)
{
	if (st)
		memset(st, 0, sizeof *st);
	if (b->dim < 1 || b->dim > DEM_MAXDIM)
		return dem_error_set(e, DEM_EINPUT, "dimension %d: expected 1, 2 or 3", b->dim);
	if (b->n > UINT32_MAX)
		return dem_error_set(e, DEM_EINPUT, "%zu objects: at most %u", b->n, UINT32_MAX);
	if (o->periodic & ((1u << b->dim) - 1))
		return run_periodic(b, o, out, st, e);
	return run(b, o, out, st, e);
}
