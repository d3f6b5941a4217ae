/* profile.c - reading and writing the profile stream (see profile.h). */
#include "io/profile.h"

#include "core/consts.h"
#include "mesh/hex.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NFIELD 13       /* sig (6), eps (6), ep */

static const char *const field[NFIELD] = {
	"sxx", "syy", "szz", "sxy", "syz", "szx",
	"exx", "eyy", "ezz", "exy", "eyz", "ezx", "ep"
};

static dem_dim_t field_dim(int f)
{
	return f < 6 ? DEM_DIM_PRESSURE : DEM_DIM_NONE;
}

void dem_profile_free(dem_profile_t *p)
{
	if (!p)
		return;
	free(p->depth);
	free(p->sig);
	free(p->eps);
	free(p->ep);
	free(p->sd);
	free(p->count);
	memset(p, 0, sizeof *p);
}

int dem_profile_alloc(dem_profile_t *p, size_t n, dem_error_t *e)
{
	size_t m = n ? n : 1;
	memset(p, 0, sizeof *p);
	p->n = n;
	p->depth = calloc(m, sizeof *p->depth);
	p->sig = calloc(6 * m, sizeof *p->sig);
	p->eps = calloc(6 * m, sizeof *p->eps);
	p->ep = calloc(m, sizeof *p->ep);
	p->sd = calloc(NFIELD * m, sizeof *p->sd);
	p->count = calloc(m, sizeof *p->count);
	if (!p->depth || !p->sig || !p->eps || !p->ep || !p->sd || !p->count) {
		dem_profile_free(p);
		return dem_error_nomem(e, "profile");
	}
	return DEM_OK;
}

/* Field f of point i, as stored. */
static double *at(const dem_profile_t *p, size_t i, int f)
{
	return f < 6 ? &p->sig[6 * i + f] : f < 12 ? &p->eps[6 * i + f - 6] : &p->ep[i];
}

/* ---- writer -------------------------------------------------------------- */

void dem_profile_header(dem_header_t *h)
{
	char name[24];
	dem_header_init(h, "profile", 1, 0);
	dem_header_add_col(h, "pass", DEM_U32, "-");
	dem_header_add_col(h, "depth", DEM_F64, "m");
	for (int f = 0; f < NFIELD; f++)
		dem_header_add_col(h, field[f], DEM_F64, f < 6 ? "Pa" : "-");
	for (int f = 0; f < NFIELD; f++) {
		snprintf(name, sizeof name, "sd_%s", field[f]);
		dem_header_add_col(h, name, DEM_F64, f < 6 ? "Pa" : "-");
	}
	dem_header_add_col(h, "n", DEM_U32, "-");
}

int dem_profile_write(dem_writer_t *w, const dem_profile_t *p, dem_error_t *e)
{
	double v[2 + 2 * NFIELD + 1];
	for (size_t i = 0; i < p->n; i++) {
		if (!(p->depth[i] >= 0) || (i && !(p->depth[i] > p->depth[i - 1])))
			return dem_error_set(e, DEM_EINPUT, "profile of pass %d: depth %g at point %zu "
					     "(depths must be >= 0 and increase)", p->pass,
					     p->depth[i], i);
		v[0] = p->pass;
		v[1] = p->depth[i];
		for (int f = 0; f < NFIELD; f++) {
			v[2 + f] = *at(p, i, f);
			v[2 + NFIELD + f] = p->sd[NFIELD * i + f];
		}
		v[2 + 2 * NFIELD] = p->count[i];
		for (int c = 0; c < 2 + 2 * NFIELD; c++)
			if (!isfinite(v[c]))
				return dem_error_set(e, DEM_EINPUT, "profile of pass %d: point %zu: "
						     "a value is not finite", p->pass, i);
		if (dem_writer_row(w, v, e))
			return e->code;
	}
	return DEM_OK;
}

/* ---- reader -------------------------------------------------------------- */

/* The columns found in the stream and their factors to SI. */
struct cols {
	int pass, depth, f[NFIELD], sd[NFIELD], n;
	double fdepth, ff[NFIELD], fsd[NFIELD];
};

static int find_cols(dem_reader_t *rd, struct cols *c, dem_error_t *e)
{
	const dem_header_t *h = dem_reader_header(rd);
	const char *name = dem_reader_name(rd);
	char sd[24];

	if (strcmp(h->kind, "profile") != 0)
		return dem_error_set(e, DEM_EINPUT, "%s: a %s stream; expected a profile stream",
				     name, h->kind);
	c->pass = dem_header_col(h, "pass");
	c->depth = dem_header_col(h, "depth");
	c->n = dem_header_col(h, "n");
	if (c->pass < 0 || c->depth < 0)
		return dem_error_set(e, DEM_EINPUT, "%s: no column '%s'", name,
				     c->pass < 0 ? "pass" : "depth");
	if (dem_header_col_factor(h, c->depth, DEM_DIM_LENGTH, name, &c->fdepth, e))
		return e->code;
	for (int f = 0; f < NFIELD; f++) {
		c->f[f] = dem_header_col(h, field[f]);
		if (c->f[f] < 0)
			return dem_error_set(e, DEM_EINPUT, "%s: no column '%s'", name, field[f]);
		if (dem_header_col_factor(h, c->f[f], field_dim(f), name, &c->ff[f], e))
			return e->code;
		/* the spreads are optional: a hand-made profile may have none */
		snprintf(sd, sizeof sd, "sd_%s", field[f]);
		c->sd[f] = dem_header_col(h, sd);
		c->fsd[f] = 1;
		if (c->sd[f] >= 0 &&
		    dem_header_col_factor(h, c->sd[f], field_dim(f), name, &c->fsd[f], e))
			return e->code;
	}
	return DEM_OK;
}

/* A growing profile. */
static int push(dem_profile_t *p, size_t *cap, dem_error_t *e)
{
	if (p->n == *cap) {
		size_t nc = *cap ? 2 * *cap : 64;
		double *d = realloc(p->depth, nc * sizeof *d), *s = NULL, *t = NULL, *q = NULL, *sd = NULL;
		unsigned *k = NULL;
		if (d)
			p->depth = d;
		if (d && (s = realloc(p->sig, 6 * nc * sizeof *s)))
			p->sig = s;
		if (s && (t = realloc(p->eps, 6 * nc * sizeof *t)))
			p->eps = t;
		if (t && (q = realloc(p->ep, nc * sizeof *q)))
			p->ep = q;
		if (q && (sd = realloc(p->sd, NFIELD * nc * sizeof *sd)))
			p->sd = sd;
		if (sd && (k = realloc(p->count, nc * sizeof *k)))
			p->count = k;
		if (!k)
			return dem_error_nomem(e, "profile");
		*cap = nc;
	}
	p->n++;
	return DEM_OK;
}

/* Read the stream; want >= 0: that pass; -1: the last; -2: every pass
 * (into *all, *nall). */
static int read_profiles(const char *path, int want, dem_profile_t *one,
			 dem_profile_t **all, int *nall, dem_error_t *e)
{
	dem_reader_t *rd = NULL;
	struct cols c;
	double v[DEM_STREAM_MAXCOL];
	dem_profile_t cur = {0}, *list = NULL;
	size_t cap = 0;
	int nlist = 0, got, found = 0, rc = DEM_OK;
	long first = -1, last = -1, npass = 0;

	if (one)
		memset(one, 0, sizeof *one);
	if ((rc = dem_reader_open(&rd, path, e)) || (rc = find_cols(rd, &c, e)))
		goto out;
	int plane = dem_header_has_word(dem_reader_header(rd), "twod", "mode=plane");
	for (;;) {
		got = dem_reader_next(rd, v, e);
		if (got < 0) {
			rc = e->code;
			goto out;
		}
		double pv = got ? v[c.pass] : 0;
		if (got && !(pv >= 0 && pv <= 2147483647.0 && pv == floor(pv))) {
			rc = dem_error_set(e, DEM_EINPUT, "%s: pass %g: expected a whole number >= 0",
					   dem_reader_where(rd), pv);
			goto out;
		}
		/* a pass ends: keep it if wanted */
		if (cur.depth && (!got || (int)pv != cur.pass)) {
			if (got && (int)pv < cur.pass) {
				rc = dem_error_set(e, DEM_EINPUT, "%s: pass %d after pass %d: the rows "
						   "must be grouped by pass, passes increasing",
						   dem_reader_where(rd), (int)pv, cur.pass);
				goto out;
			}
			if (want == -2) {
				dem_profile_t *l = realloc(list, (size_t)(nlist + 1) * sizeof *l);
				if (!l) {
					rc = dem_error_nomem(e, "profiles");
					goto out;
				}
				list = l;
				list[nlist++] = cur;
			} else if (want == -1 || want == cur.pass) {
				dem_profile_free(one);
				*one = cur;
				found = 1;
			} else {
				dem_profile_free(&cur);
			}
			memset(&cur, 0, sizeof cur);
			cap = 0;
		}
		if (!got)
			break;
		if (!cur.depth) {
			cur.pass = (int)pv;
			cur.plane = plane;
			npass++;
			if (first < 0)
				first = cur.pass;
			last = cur.pass;
		}
		if ((rc = push(&cur, &cap, e)))
			goto out;
		size_t i = cur.n - 1;
		double d = v[c.depth] * c.fdepth;
		if (!(d >= 0) || (i && !(d > cur.depth[i - 1]))) {
			rc = dem_error_set(e, DEM_EINPUT, "%s: depth %g m: depths must be >= 0 and "
					   "increase within a pass", dem_reader_where(rd), d);
			goto out;
		}
		cur.depth[i] = d;
		for (int f = 0; f < NFIELD; f++) {
			*at(&cur, i, f) = v[c.f[f]] * c.ff[f];
			double s = c.sd[f] >= 0 ? v[c.sd[f]] * c.fsd[f] : 0;
			if (s < 0) {
				rc = dem_error_set(e, DEM_EINPUT, "%s: sd_%s %g: a spread is not negative",
						   dem_reader_where(rd), field[f], s);
				goto out;
			}
			cur.sd[NFIELD * i + f] = s;
		}
		double n = c.n >= 0 ? v[c.n] : 0;
		if (!(n >= 0 && n <= 4294967295.0 && n == floor(n))) {
			rc = dem_error_set(e, DEM_EINPUT, "%s: n %g: expected a count",
					   dem_reader_where(rd), n);
			goto out;
		}
		cur.count[i] = (unsigned)n;
	}
	if (npass == 0) {
		rc = dem_error_set(e, DEM_EINPUT, "%s: no profile: the stream has no rows",
				   dem_reader_name(rd));
	} else if (want >= 0 && !found) {
		rc = dem_error_set(e, DEM_EINPUT, "%s: no pass %d in the profile stream "
				   "(%ld passes, %ld to %ld)", dem_reader_name(rd), want, npass,
				   first, last);
	}
out:
	dem_profile_free(&cur);
	if (rc) {
		dem_profile_free(one);
		for (int k = 0; k < nlist; k++)
			dem_profile_free(&list[k]);
		free(list);
	} else if (all) {
		*all = list;
		*nall = nlist;
	}
	dem_reader_close(rd);
	return rc;
}

int dem_profile_read(const char *path, int pass, dem_profile_t *p,
		     dem_error_t *e)
{
	return read_profiles(path, pass < 0 ? -1 : pass, p, NULL, NULL, e);
}

int dem_profile_read_all(const char *path, dem_profile_t **ps, int *np,
			 dem_error_t *e)
{
	*ps = NULL;
	*np = 0;
	return read_profiles(path, -2, NULL, ps, np, e);
}

void dem_profile_eval(const dem_profile_t *p, double depth, double sig[6],
		      double eps[6], double *ep)
{
	size_t lo = 0, hi;
	double t = 0;

	if (p->n == 0) {
		if (sig)
			memset(sig, 0, 6 * sizeof *sig);
		if (eps)
			memset(eps, 0, 6 * sizeof *eps);
		if (ep)
			*ep = 0;
		return;
	}
	if (p->n == 1 || !(depth > p->depth[0])) {
		hi = 0;
	} else if (depth >= p->depth[p->n - 1]) {
		lo = hi = p->n - 1;
	} else {
		/* the interval depth[lo] <= depth < depth[hi], hi = lo + 1 */
		hi = p->n - 1;
		while (hi - lo > 1) {
			size_t mid = lo + (hi - lo) / 2;
			if (p->depth[mid] <= depth)
				lo = mid;
			else
				hi = mid;
		}
		t = (depth - p->depth[lo]) / (p->depth[hi] - p->depth[lo]);
	}
	for (int f = 0; f < NFIELD; f++) {
		double a = *at(p, lo, f), b = *at(p, hi, f);
		double x = t == 0 ? a : a + t * (b - a);
		if (f < 6 && sig)
			sig[f] = x;
		else if (f >= 6 && f < 12 && eps)
			eps[f - 6] = x;
		else if (f == 12 && ep)
			*ep = x;
	}
}

/* ---- profiles of a state frame ------------------------------------------- */

/* Centroid and volume of element el in the reference state. */
static void elem_geom(const dem_mesh_t *m, size_t el, double c[3], double *vol)
{
	if (m->nx > 0) {
		size_t nxy = (size_t)m->nx * (size_t)m->ny;
		int i = (int)(el % (size_t)m->nx), j = (int)(el / (size_t)m->nx % (size_t)m->ny),
		    k = (int)(el / nxy);
		c[0] = 0.5 * (m->gx[i] + m->gx[i + 1]);
		c[1] = 0.5 * (m->gy[j] + m->gy[j + 1]);
		c[2] = 0.5 * (m->gz[k] + m->gz[k + 1]);
		*vol = (m->gx[i + 1] - m->gx[i]) * (m->gy[j + 1] - m->gy[j]) *
		       (m->gz[k + 1] - m->gz[k]);
		return;
	}
	double x[24];
	c[0] = c[1] = c[2] = 0;
	for (int a = 0; a < 8; a++)
		for (int d = 0; d < 3; d++) {
			x[8 * d + a] = m->X[3 * (size_t)m->hex[8 * el + a] + d];
			c[d] += 0.125 * x[8 * d + a];
		}
	*vol = dem_hex_volume(x);
}

static int in_region(const dem_profile_opts_t *o, double x, double y)
{
	return x >= o->lo[0] && x <= o->hi[0] && y >= o->lo[1] && y <= o->hi[1];
}

static double fval(const double *sig, const double *eps, const double *ep,
		   size_t el, int f)
{
	return f < 6 ? sig[6 * el + f] : f < 12 ? eps[6 * el + f - 6] : ep[el];
}

int dem_profile_compute(const dem_mesh_t *m, const double *sig,
			const double *eps, const double *ep,
			const dem_profile_opts_t *o, dem_profile_t *p,
			dem_error_t *e)
{
	int layers = !(o->bin > 0);
	double ztop = -HUGE_VAL, zbot = HUGE_VAL;
	size_t ng;

	memset(p, 0, sizeof *p);
	if (layers && m->nx <= 0)
		return dem_error_set(e, DEM_EINPUT, "element layers need a structured mesh "
				     "(a '# grid' line in the state stream); use depth bins");
	for (size_t n = 0; n < m->nn; n++) {
		ztop = fmax(ztop, m->X[3 * n + 2]);
		zbot = fmin(zbot, m->X[3 * n + 2]);
	}
	if (layers) {
		ng = (size_t)m->nz;
	} else {
		double nb = floor((ztop - zbot) / o->bin) + 1;
		if (!(nb <= 1e7))
			return dem_error_set(e, DEM_EINPUT, "depth bins of %g m: too many (%g) for "
					     "a block %g m thick", o->bin, nb, ztop - zbot);
		ng = (size_t)nb;
	}

	/* volume-weighted sums shifted by each group's first sample (x0), so a
	 * group of equal values averages to that value exactly */
	double *W = calloc(ng, sizeof *W), *d0 = calloc(ng, sizeof *d0),
	       *dS = calloc(ng, sizeof *dS), *x0 = calloc(ng * NFIELD, sizeof *x0),
	       *S1 = calloc(ng * NFIELD, sizeof *S1), *S2 = calloc(ng * NFIELD, sizeof *S2);
	unsigned *cnt = calloc(ng, sizeof *cnt);
	int rc = DEM_OK;
	if (!W || !d0 || !dS || !x0 || !S1 || !S2 || !cnt) {
		rc = dem_error_nomem(e, "profile sums");
		goto out;
	}
	size_t nxy = (size_t)(m->nx > 0 ? m->nx * m->ny : 1);
	for (int pass = 0; pass < 2; pass++) {
		for (size_t el = 0; el < m->ne; el++) {
			double c[3], vol;
			elem_geom(m, el, c, &vol);
			if (!in_region(o, c[0], c[1]))
				continue;
			/* Pappus: the ring's volume, 2 pi |r_c| times the
			 * section's area (the y extent, the same for every
			 * element of a 2D stream, cancels in the means) */
			if (o->axisym)
				vol *= 2 * DEM_PI * fabs(c[0]);
			double depth = ztop - c[2];
			size_t g = layers ? el / nxy : (size_t)(depth / o->bin);
			if (g >= ng)
				g = ng - 1;
			if (pass == 0) {
				if (cnt[g]++ == 0) {
					d0[g] = depth;
					for (int f = 0; f < NFIELD; f++)
						x0[NFIELD * g + f] = fval(sig, eps, ep, el, f);
				}
				W[g] += vol;
				dS[g] += vol * (depth - d0[g]);
				for (int f = 0; f < NFIELD; f++)
					S1[NFIELD * g + f] += vol * (fval(sig, eps, ep, el, f) - x0[NFIELD * g + f]);
			} else {
				for (int f = 0; f < NFIELD; f++) {
					double dx = fval(sig, eps, ep, el, f) - S1[NFIELD * g + f];
					S2[NFIELD * g + f] += vol * dx * dx;
				}
			}
		}
		if (pass == 1)
			break;
		/* the means, kept in S1 for the second pass */
		for (size_t g = 0; g < ng; g++)
			for (int f = 0; f < NFIELD && cnt[g]; f++)
				S1[NFIELD * g + f] = W[g] > 0 ? x0[NFIELD * g + f] + S1[NFIELD * g + f] / W[g]
							       : x0[NFIELD * g + f];
	}
	size_t np = 0;
	for (size_t g = 0; g < ng; g++)
		np += cnt[g] > 0;
	if (np == 0) {
		rc = dem_error_set(e, DEM_EINPUT, "no element centroid in the region x %g to %g m, "
				   "y %g to %g m", o->lo[0], o->hi[0], o->lo[1], o->hi[1]);
		goto out;
	}
	if ((rc = dem_profile_alloc(p, np, e)))
		goto out;
	size_t i = 0;
	for (size_t q = 0; q < ng; q++) {
		size_t g = layers ? ng - 1 - q : q;     /* depth increasing */
		if (!cnt[g])
			continue;
		if (layers)
			p->depth[i] = ztop - 0.5 * (m->gz[g] + m->gz[g + 1]);
		else
			p->depth[i] = W[g] > 0 ? d0[g] + dS[g] / W[g] : d0[g];
		for (int f = 0; f < NFIELD; f++) {
			*at(p, i, f) = S1[NFIELD * g + f];
			p->sd[NFIELD * i + f] = W[g] > 0 ? sqrt(S2[NFIELD * g + f] / W[g]) : 0;
		}
		p->count[i] = cnt[g];
		i++;
	}
out:
	free(W);
	free(d0);
	free(dS);
	free(x0);
	free(S1);
	free(S2);
	free(cnt);
	return rc;
}

/* ---- surface metrics ----------------------------------------------------- */

int dem_surface_compute(const dem_mesh_t *m, const double *u, const double *ep,
			const dem_profile_opts_t *o, dem_surface_t *s,
			dem_error_t *e)
{
	memset(s, 0, sizeof *s);
	if (m->nx <= 0)
		return dem_error_set(e, DEM_EINPUT, "surface metrics need a structured mesh "
				     "(a '# grid' line in the state stream)");
	int nx = m->nx, ny = m->ny, nz = m->nz, w1 = nx + 1;
	size_t nt = (size_t)(nx + 1) * (size_t)(ny + 1);
	double *w = calloc(nt, sizeof *w);
	unsigned char *faces = calloc(nt, 1);  /* region faces around each node */
	unsigned char *xside = calloc(nt, 1);  /* 1: a region face at lower x, 2: at higher x */
	double ytot = m->gy[ny] - m->gy[0];
	int *label = malloc(nt * sizeof *label), *stack = malloc(nt * sizeof *stack);
	int rc = DEM_OK;

	if (!w || !faces || !xside || !label || !stack) {
		rc = dem_error_nomem(e, "surface");
		goto out;
	}
	/* node weights: a quarter of each region face around the node */
	for (int j = 0; j < ny; j++)
		for (int i = 0; i < nx; i++) {
			double xc = 0.5 * (m->gx[i] + m->gx[i + 1]), yc = 0.5 * (m->gy[j] + m->gy[j + 1]);
			if (!in_region(o, xc, yc))
				continue;
			double r0 = m->gx[i], r1 = m->gx[i + 1], a, f[2] = {0.25, 0.25};
			if (o->axisym) {
				/* the ring [r0, r1], shared by the row's faces in
				 * y; each node the integral of its shape function */
				a = DEM_PI * fabs(r1 * r1 - r0 * r0) * (m->gy[j + 1] - m->gy[j]) / ytot;
				double rs = fabs(r0) + fabs(r1);
				if (rs > 0) {
					f[0] = (2 * fabs(r0) + fabs(r1)) / (6 * rs);
					f[1] = (fabs(r0) + 2 * fabs(r1)) / (6 * rs);
				}
			} else {
				a = (r1 - r0) * (m->gy[j + 1] - m->gy[j]);
			}
			s->area += a;
			if (ep && ep[dem_mesh_elem(m, i, j, nz - 1)] > o->ep_threshold)
				s->plastic += a;
			for (int c = 0; c < 4; c++) {
				size_t q = (size_t)(i + (c & 1)) + (size_t)w1 * (size_t)(j + (c >> 1));
				w[q] += f[c & 1] * a;
				faces[q]++;
				xside[q] |= (unsigned char)((c & 1) ? 1 : 2);
			}
		}
	if (!(s->area > 0)) {
		rc = dem_error_set(e, DEM_EINPUT, "no top face in the region x %g to %g m, "
				   "y %g to %g m", o->lo[0], o->hi[0], o->lo[1], o->hi[1]);
		goto out;
	}
#define UZ(q) (u[3 * ((q) + nt * (size_t)nz) + 2])
	double mean = 0, cov = 0;
	for (size_t q = 0; q < nt; q++)
		mean += w[q] * UZ(q);
	mean /= s->area;
	for (size_t q = 0; q < nt; q++) {
		if (!w[q])
			continue;
		double d = -UZ(q);
		s->ra += w[q] * fabs(UZ(q) - mean);
		if (d > o->threshold)
			cov += w[q];
		if (d > s->depth_max)
			s->depth_max = d;
	}
	s->ra /= s->area;
	s->indented = fmin(1, cov / s->area);
	s->plastic = fmin(1, s->plastic / s->area);

	/* dimples: patches of indented region nodes joined along grid lines */
	for (size_t q = 0; q < nt; q++)
		label[q] = w[q] > 0 && -UZ(q) > o->threshold ? 0 : -1;
	double sum_depth = 0, sum_radius = 0;
	for (size_t q0 = 0; q0 < nt; q0++) {
		if (label[q0] != 0)
			continue;
		int top = 0, cut = 0;
		double area = 0, deep = 0;
		stack[top++] = (int)q0;
		label[q0] = 1;
		while (top) {
			int q = stack[--top], i = q % w1, j = q / w1;
			area += w[q];
			deep = fmax(deep, -UZ((size_t)q));
			/* on the region's edge; in axisymmetry only at its
			 * ends in r, the axis excepted */
			if (o->axisym)
				cut |= xside[q] != 3 && !(i == 0 && m->gx[0] == 0);
			else
				cut |= faces[q] < 4;
			int nb[4] = {i > 0 ? q - 1 : -1, i < nx ? q + 1 : -1,
				     j > 0 ? q - w1 : -1, j < ny ? q + w1 : -1};
			for (int k = 0; k < 4; k++)
				if (nb[k] >= 0 && label[nb[k]] == 0) {
					label[nb[k]] = 1;
					stack[top++] = nb[k];
				}
		}
		s->patches++;
		if (!cut) {
			s->dimples++;
			sum_depth += deep;
			sum_radius += sqrt(area / DEM_PI);
		}
	}
#undef UZ
	if (s->dimples) {
		s->depth_mean = sum_depth / (double)s->dimples;
		s->radius = sum_radius / (double)s->dimples;
	}
out:
	free(w);
	free(faces);
	free(xside);
	free(label);
	free(stack);
	return rc;
}
