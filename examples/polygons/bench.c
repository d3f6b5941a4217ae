/* bench.c - the overlap of two convex polygons (lib/contact/polygon.h):
 * the linear algorithm with the bounding-box clip of Ch. 4.3.2 against
 * the same without the clip and against full Sutherland-Hodgman, for
 * agreement and for time per pair.
 *
 *   bench agree N SEED TAU   N random pairs of each family (polygen.h of
 *                            tests/unit), one line each:
 *                            agree FAMILY PAIRS OVERLAPS dS_clip dS_plain
 *                            dc_clip dc_plain NVMAX
 *                            dS: the largest |S - S_ref| / L^2, dc: the
 *                            largest |c - c_ref| / L over the overlaps above
 *                            1e-6 L^2 (L the smaller polygon's bounding-box
 *                            diagonal), NVMAX the largest points of a result
 *                            over n + m (at most 1)
 *   bench time SHAPE SET N REPS SEED TAU
 *                            N pairs of SHAPE (sq2, sq5, sq15: superquadrics
 *                            a = 4.5, b = 3.5 with m = 2, 5, 15 and tolerance
 *                            TAU; tri: an equilateral triangle, square: a
 *                            square, of the same area as the m = 2 one), each
 *                            turned at random, in SET:
 *                              contact    the second body moved along a random
 *                                         direction until the overlap is a
 *                                         random fraction in (0, 1 %] of the
 *                                         area (a contact of a DE run)
 *                              candidate  the second body's centre at a random
 *                                         point within the sum of the two
 *                                         circumradii (a detector's candidate
 *                                         pairs: some apart, some deep)
 *                            then REPS rounds; each round times the three
 *                            methods on all N pairs, in turn, each repeated
 *                            until it has run 0.2 s of CPU time, one line a
 *                            round:
 *                            time SHAPE SET NV ROUND ns_clip ns_plain ns_full
 *                            STEPS_clip STEPS_plain (mean edge pairs a pair)
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "contact/polygon.h"
#include "polygen.h"

#define MAXV 4096

/* the process's CPU time: the machine of the reports is shared, and a
 * process waiting for a core does not count */
static double now(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double P[MAXV][2], Q[MAXV][2], V[3][2 * MAXV][2], W[4 * MAXV][2];
static unsigned char SD[3][2 * MAXV];

static void die(const char *msg)
{
	fprintf(stderr, "bench: %s\n", msg);
	exit(2);
}

/* ---- agreement ------------------------------------------------------------ */

static const struct {
	const char *name;
	int kp, kq;
} families[] = {
	{ "superquadric-superquadric", POLY_SQ, POLY_SQ },
	{ "triangle-triangle", POLY_TRI, POLY_TRI },
	{ "square-square", POLY_SQUARE, POLY_SQUARE },
	{ "superquadric-triangle", POLY_SQ, POLY_TRI },
	{ "triangle-square", POLY_TRI, POLY_SQUARE },
	{ "grid-grid (degenerate)", POLY_GRID, POLY_GRID },
};

static int agree(long N, unsigned long seed, double tau)
{
	for (size_t f = 0; f < sizeof families / sizeof *families; f++) {
		unsigned long s = seed + f;
		double dS[2] = { 0, 0 }, dc[2] = { 0, 0 }, nvmax = 0;
		long hits = 0;
		for (long it = 0; it < N; it++) {
			int n = pg_poly(&s, families[f].kp, tau, MAXV, P);
			int m = pg_poly(&s, families[f].kq, tau, MAXV, Q);
			if (n > MAXV || m > MAXV)
				die("a polygon has too many points: raise MAXV or TAU");
			dem_overlap_t o[3];
			dem_polygon_chase(n, (const double (*)[2])P, m, (const double (*)[2])Q, 1, V[0],
			                  SD[0], W, &o[0]);
			dem_polygon_chase(n, (const double (*)[2])P, m, (const double (*)[2])Q, 0, V[1],
			                  SD[1], W, &o[1]);
			dem_polygon_clip(n, (const double (*)[2])P, m, (const double (*)[2])Q, V[2], SD[2],
			                 W, &o[2]);
			double L = fmin(pg_size(n, (const double (*)[2])P), pg_size(m, (const double (*)[2])Q));
			hits += o[2].S > 0;
			for (int k = 0; k < 2; k++) {
				dS[k] = fmax(dS[k], fabs(o[k].S - o[2].S) / (L * L));
				if (fmin(o[k].S, o[2].S) > 1e-6 * L * L)
					dc[k] = fmax(dc[k], hypot(o[k].c[0] - o[2].c[0], o[k].c[1] - o[2].c[1]) / L);
				nvmax = fmax(nvmax, (double)o[k].nv / (n + m));
			}
		}
		printf("agree\t%s\t%ld\t%ld\t%.3g\t%.3g\t%.3g\t%.3g\t%.3g\n", families[f].name, N, hits,
		       dS[0], dS[1], dc[0], dc[1], nvmax);
	}
	return 0;
}

/* ---- timing --------------------------------------------------------------- */

typedef struct pairset {
	int n;                /* points of each polygon */
	long N;
	double (*p)[2], (*q)[2];  /* N n points each */
} pairset_t;

/* the body's points in its own frame (centroid 0); returns n */
static int shape(const char *name, double tau, double (*v)[2])
{
	double a = 4.5, b = 3.5;
	if (!strcmp(name, "sq2") || !strcmp(name, "sq5") || !strcmp(name, "sq15")) {
		double m = atof(name + 2);
		int n = dem_superquadric_polygon(a, b, m, tau, MAXV, v);
		if (n < 0 || n > MAXV)
			die("bad superquadric or too many points");
		return n;
	}
	double A = DEM_PI * a * b;  /* the m = 2 body's area */
	if (!strcmp(name, "tri")) {
		double r = sqrt(4 * A / (3 * sqrt(3.0)));  /* circumradius: A = 3 sqrt(3)/4 r^2 */
		for (int i = 0; i < 3; i++)
			v[i][0] = r * cos(2 * DEM_PI * i / 3), v[i][1] = r * sin(2 * DEM_PI * i / 3);
		return 3;
	}
	if (!strcmp(name, "square")) {
		double h = 0.5 * sqrt(A);
		const double sq[4][2] = { { h, -h }, { h, h }, { -h, h }, { -h, -h } };
		memcpy(v, sq, sizeof sq);
		return 4;
	}
	die("unknown shape (sq2, sq5, sq15, tri, square)");
	return 0;
}

static double overlap_at(int n, const double (*p)[2], const double (*q0)[2], const double u[2],
                         double d, double th, double (*q)[2])
{
	double x[2] = { d * u[0], d * u[1] };
	dem_polygon_place(n, q0, x, th, q);
	dem_overlap_t o;
	dem_polygon_clip(n, p, n, (const double (*)[2])q, V[2], SD[2], W, &o);
	return o.S;
}

static void make_pairs(const char *shp, const char *set, long N, unsigned long seed, double tau,
                       pairset_t *ps)
{
	static double v0[MAXV][2];
	int n = shape(shp, tau, v0);
	double R = 0;
	for (int i = 0; i < n; i++)
		R = fmax(R, hypot(v0[i][0], v0[i][1]));
	dem_area_props_t pr;
	dem_polygon_props(n, (const double (*)[2])v0, &pr);
	ps->n = n, ps->N = N;
	ps->p = malloc((size_t)N * (size_t)n * sizeof *ps->p);
	ps->q = malloc((size_t)N * (size_t)n * sizeof *ps->q);
	if (!ps->p || !ps->q)
		die("out of memory");
	int contact = !strcmp(set, "contact");
	if (!contact && strcmp(set, "candidate"))
		die("unknown set (contact, candidate)");
	unsigned long s = seed;
	for (long k = 0; k < N; k++) {
		double (*p)[2] = ps->p + k * n, (*q)[2] = ps->q + k * n;
		double zero[2] = { 0, 0 }, th = 2 * DEM_PI * pg_urand(&s), tq = 2 * DEM_PI * pg_urand(&s);
		double phi = 2 * DEM_PI * pg_urand(&s), u[2] = { cos(phi), sin(phi) };
		dem_polygon_place(n, (const double (*)[2])v0, zero, th, p);
		if (!contact) {
			double d = 2 * R * sqrt(pg_urand(&s));
			overlap_at(n, (const double (*)[2])p, (const double (*)[2])v0, u, d, tq, q);
			continue;
		}
		/* bisect the distance for S = f A, f in (0, 1 %] */
		double f = 0.01 * (1 - pg_urand(&s)), lo = 0, hi = 2 * R;
		for (int it = 0; it < 60; it++) {
			double mid = 0.5 * (lo + hi);
			if (overlap_at(n, (const double (*)[2])p, (const double (*)[2])v0, u, mid, tq, q) > f * pr.A)
				lo = mid;
			else
				hi = mid;
		}
		overlap_at(n, (const double (*)[2])p, (const double (*)[2])v0, u, lo, tq, q);
	}
}

/* one method on all pairs, repeated for at least 0.2 s: ns a pair, and the
 * mean steps a pair */
static double time_method(const pairset_t *ps, int method, double *steps, double *sink)
{
	long calls = 0, st = 0;
	double t0 = now(), t;
	int n = ps->n;
	do {
		for (long k = 0; k < ps->N; k++) {
			dem_overlap_t o;
			const double (*p)[2] = (const double (*)[2])(ps->p + k * n);
			const double (*q)[2] = (const double (*)[2])(ps->q + k * n);
			if (method < 2)
				dem_polygon_chase(n, p, n, q, method == 0, V[0], SD[0], W, &o);
			else
				dem_polygon_clip(n, p, n, q, V[0], SD[0], W, &o);
			*sink += o.S;
			st += o.steps;
		}
		calls += ps->N;
		t = now() - t0;
	} while (t < 0.2);
	*steps = (double)st / (double)calls;
	return 1e9 * t / (double)calls;
}

static int timing(const char *shp, const char *set, long N, int reps, unsigned long seed,
                  double tau)
{
	pairset_t ps;
	make_pairs(shp, set, N, seed, tau, &ps);
	double sink = 0;
	for (int r = 0; r < reps; r++) {
		double ns[3], st[3];
		for (int m = 0; m < 3; m++)
			ns[m] = time_method(&ps, m, &st[m], &sink);
		printf("time\t%s\t%s\t%d\t%d\t%.1f\t%.1f\t%.1f\t%.2f\t%.2f\n", shp, set, ps.n, r, ns[0],
		       ns[1], ns[2], st[0], st[1]);
		fflush(stdout);
	}
	if (sink < 0)
		printf("# %g\n", sink);  /* keeps the calls */
	free(ps.p);
	free(ps.q);
	return 0;
}

int main(int argc, char **argv)
{
	if (argc == 5 && !strcmp(argv[1], "agree"))
		return agree(atol(argv[2]), strtoul(argv[3], NULL, 10), atof(argv[4]));
	if (argc == 8 && !strcmp(argv[1], "time"))
		return timing(argv[2], argv[3], atol(argv[4]), atoi(argv[5]),
		              strtoul(argv[6], NULL, 10), atof(argv[7]));
	fprintf(stderr, "usage: bench agree N SEED TAU\n"
	                "       bench time SHAPE SET N REPS SEED TAU\n");
	return 2;
}
