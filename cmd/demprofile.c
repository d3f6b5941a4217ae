/* demprofile - residual profiles and surface metrics of a state stream
 * (Han 2004, Ch. 8.4).
 *
 *   demprofile [OPTION]... [FILE]
 *
 * Reads a state stream (demshot's), and for each pass averages the stress,
 * total strain and effective plastic strain over the elements of the
 * impacted region at each depth (element layers or depth bins), with their
 * spread and count; writes the profile stream demform reads.  Per pass it
 * also measures the top surface (coverage, dimples, roughness) and can
 * write a saturation table (a field's surface and peak values per pass).
 * The last frame of a pass is its end-of-pass state.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/afile.h"
#include "core/cli.h"
#include "core/cost.h"
#include "core/fmt.h"
#include "io/profile.h"
#include "io/scene.h"
#include "io/state.h"
#include "io/stream.h"

#define PROG "demprofile"

enum { OPT_PASS = DEM_OPT_PROGRAM, OPT_AREA, OPT_MARGIN, OPT_BINS, OPT_BIN_SIZE,
       OPT_THRESHOLD, OPT_PLASTIC, OPT_SURFACE, OPT_SATURATION, OPT_FIELD };

static const dem_opt_t options[] = {
	{"pass", OPT_PASS, "PASS", "the pass to profile: a pass number, last or all (default all)"},
	{"area", OPT_AREA, "AX:AY", "sides of the impacted area, centred on profile.center (default: the stream's '# area', else the whole top face)"},
	{"margin", OPT_MARGIN, "L", "leave out L inside each edge of the area (default 10 % of its shorter side)"},
	{"bins", OPT_BINS, "N", "average over N depth bins through the block instead of element layers"},
	{"bin-size", OPT_BIN_SIZE, "L", "average over depth bins L deep instead of element layers"},
	{"threshold", OPT_THRESHOLD, "D", "indentation that counts as dimpled, for the indented share (default 1um)"},
	{"plastic-threshold", OPT_PLASTIC, "EP", "plastic strain that counts as covered, for the plastic coverage (default 0.002)"},
	{"field", OPT_FIELD, "NAME", "the field of the saturation table: sxx ... szx, exx ... ezx, ep (default sxx)"},
	{"surface", OPT_SURFACE, "FILE", "write the surface metrics per pass to FILE (a table)"},
	{"saturation", OPT_SATURATION, "FILE", "write the saturation table (surface and peak values per pass) to FILE"},
	DEM_OPTS_COMMON,
	{0}
};

static const char usage[] = "Usage: demprofile [OPTION]... [FILE]\n";
static const char purpose[] =
	"Average the stress, strain and plastic strain of a state stream (FILE or\n"
	"standard input) over the impacted region at each depth, pass by pass, and\n"
	"write them as a profile stream; measure the peened surface.\n";
static const char epilogue[] =
	"Examples:\n"
	"  demshot -s strip.yaml < shots | demprofile > strip.profile\n"
	"  demprofile --pass last --bins 40 --surface surf.txt run.state\n"
	"  demprofile --saturation sat.txt -o /dev/null run.state\n"
	"\nSee demprofile(1), dem-scene(5) and dem-streams(5).\n";

static const char *const fields[] = {
	"sxx", "syy", "szz", "sxy", "syz", "szx",
	"exx", "eyy", "ezz", "exy", "eyz", "ezx", "ep", NULL
};

enum { PASS_ALL = -2, PASS_LAST = -1 };

struct cmdline {
	dem_common_t com;
	const char *input;
	long pass;                      /* PASS_ALL, PASS_LAST or a pass */
	const char *surface, *saturation;
};

static int parse_cmdline(int argc, char **argv, struct cmdline *cl)
{
	dem_cli_t c;
	dem_common_t *m = &cl->com;
	int k, bins = 0, bin_size = 0;

	memset(cl, 0, sizeof *cl);
	cl->pass = PASS_ALL;
	if (dem_common_init(m, argc) || dem_cli_init(&c, PROG, options, usage, purpose, epilogue))
		return DEM_EIO;
	/* (of the common options, --seed and --accuracy have no use here:
	 * nothing is random, no knob) */
	while ((k = dem_cli_option(&c, m, argc, argv)) != -1) {
		switch (k) {
		case OPT_PASS:
			if (strcmp(optarg, "all") == 0) {
				cl->pass = PASS_ALL;
			} else if (strcmp(optarg, "last") == 0) {
				cl->pass = PASS_LAST;
			} else {
				unsigned long p;
				if (dem_cli_ulong(&c, "--pass", optarg, 0, 4294967295UL, &p) == 0)
					cl->pass = (long)p;
			}
			break;
		case OPT_AREA:
			if (dem_common_override_vector(m, "profile.area", optarg, "--area"))
				return DEM_EIO;
			break;
		case OPT_MARGIN: dem_common_override(m, "profile.margin", optarg, "--margin"); break;
		case OPT_BINS:
			bins = 1;
			dem_common_override(m, "profile.bins", optarg, "--bins");
			break;
		case OPT_BIN_SIZE:
			bin_size = 1;
			dem_common_override(m, "profile.bin_size", optarg, "--bin-size");
			break;
		case OPT_THRESHOLD: dem_common_override(m, "profile.threshold", optarg, "--threshold"); break;
		case OPT_PLASTIC:
			dem_common_override(m, "profile.plastic_threshold", optarg, "--plastic-threshold");
			break;
		case OPT_FIELD: dem_common_override(m, "profile.field", optarg, "--field"); break;
		case OPT_SURFACE: cl->surface = optarg; break;
		case OPT_SATURATION: cl->saturation = optarg; break;
		default: break;
		}
	}
	if (c.done < 0) {
		cl->input = dem_cli_operand(&c, argc, argv, "input");
		if (bins && bin_size)
			dem_cli_error(&c, "--bins and --bin-size: give one or the other");
	}
	return dem_cli_done(&c);
}

struct settings {
	double area[2], center[2];      /* area NAN: not in the scene */
	double margin;                  /* NAN: 10 % of the shorter side */
	long bins;
	double bin_size, threshold, ep_threshold;
	int field;
};

static int read_scene(dem_scene_t *s, struct settings *st, dem_error_t *e)
{
	static const char *const sections[] = {"profile", NULL};
	static const double zero2[2] = {0, 0};

	st->area[0] = st->area[1] = NAN;
	st->margin = NAN;
	if (dem_scene_vector(s, "profile.area", DEM_DIM_LENGTH, 2, NULL, DEM_SCENE_GT0, HUGE_VAL, st->area, e) ||
	    dem_scene_vector(s, "profile.center", DEM_DIM_LENGTH, 2, zero2, -HUGE_VAL, HUGE_VAL, st->center, e) ||
	    dem_scene_quantity(s, "profile.margin", DEM_DIM_LENGTH, NAN, 0, HUGE_VAL, &st->margin, e) ||
	    dem_scene_int(s, "profile.bins", 0, 0, 1000000, &st->bins, e) ||
	    dem_scene_quantity(s, "profile.bin_size", DEM_DIM_LENGTH, 0, 0, HUGE_VAL, &st->bin_size, e) ||
	    dem_scene_quantity(s, "profile.threshold", DEM_DIM_LENGTH, 1e-6, 0, HUGE_VAL, &st->threshold, e) ||
	    /* the plastic strain of the 0.2 % offset yield (Rp0.2, ISO 6892-1,
	     * ASTM E8): what a tensile test counts as having yielded */
	    dem_scene_quantity(s, "profile.plastic_threshold", DEM_DIM_NONE, 0.002, 0, 1, &st->ep_threshold, e) ||
	    dem_scene_choice(s, "profile.field", fields, 0, &st->field, e))
		return e->code;
	if (st->bins > 0 && st->bin_size > 0)
		return dem_scene_error(s, "profile.bin_size", e, "profile.bins is given too: "
				       "give one or the other");
	return dem_scene_check(s, sections, e);
}

/* The region: the area (scene, else the stream's "# area", else the whole
 * top face) less the margin.  *from says which. */
static int find_region(const struct settings *st, dem_state_reader_t *r,
		       dem_profile_opts_t *o, const char **from, dem_error_t *e)
{
	const dem_mesh_t *m = dem_state_mesh(r);
	const char *a = dem_header_get(dem_state_header(r), "area");
	double lo[2], hi[2];

	if (!isnan(st->area[0])) {
		for (int d = 0; d < 2; d++) {
			lo[d] = st->center[d] - 0.5 * st->area[d];
			hi[d] = st->center[d] + 0.5 * st->area[d];
		}
		*from = "scene";
	} else if (a) {
		char extra;
		if (sscanf(a, "%lf %lf %lf %lf %c", &lo[0], &lo[1], &hi[0], &hi[1], &extra) != 4 ||
		    !(lo[0] < hi[0]) || !(lo[1] < hi[1]) || !isfinite(lo[0] + lo[1] + hi[0] + hi[1]))
			return dem_error_set(e, DEM_EINPUT, "%s: '# area %s': expected XLO YLO XHI YHI "
					     "in metres, lower corner first", dem_state_name(r), a);
		*from = "stream";
	} else {
		lo[0] = lo[1] = HUGE_VAL;
		hi[0] = hi[1] = -HUGE_VAL;
		for (size_t n = 0; n < m->nn; n++)
			for (int d = 0; d < 2; d++) {
				lo[d] = fmin(lo[d], m->X[3 * n + d]);
				hi[d] = fmax(hi[d], m->X[3 * n + d]);
			}
		*from = "block";
	}
	double margin = isnan(st->margin) ? 0.1 * fmin(hi[0] - lo[0], hi[1] - lo[1]) : st->margin;
	for (int d = 0; d < 2; d++) {
		o->lo[d] = lo[d] + margin;
		o->hi[d] = hi[d] - margin;
		if (!(o->lo[d] < o->hi[d]))
			return dem_error_set(e, DEM_EINPUT, "a margin of %g m leaves nothing of the "
					     "area x %g to %g m, y %g to %g m (from the %s)", margin,
					     lo[0], hi[0], lo[1], hi[1], *from);
	}
	o->threshold = st->threshold;
	o->ep_threshold = st->ep_threshold;
	/* an axisymmetric block's stream (demshot: "# twod mode=axisym") */
	o->axisym = dem_header_has_word(dem_state_header(r), "twod", "mode=axisym");
	o->bin = st->bin_size;
	if (st->bins > 0) {
		double zlo = HUGE_VAL, zhi = -HUGE_VAL;
		for (size_t n = 0; n < m->nn; n++) {
			zlo = fmin(zlo, m->X[3 * n + 2]);
			zhi = fmax(zhi, m->X[3 * n + 2]);
		}
		o->bin = (zhi - zlo) / (double)st->bins;
	}
	return DEM_OK;
}

/* Numbers in the tables: the shortest text that reads back exactly. */
static void put(FILE *f, double v, const char *sep)
{
	char buf[32];
	dem_fmt_double(buf, v == 0 ? 0 : v);    /* no "-0" */
	fputs(buf, f);
	fputs(sep, f);
}

/* One pass's results, held until the pass's last frame is known. */
struct result {
	int have;
	unsigned pass;
	double time;
	dem_profile_t p;
	int has_surface;
	dem_surface_t s;
};

struct run {
	const struct cmdline *cl;
	const struct settings *st;
	/* for opening the outputs at the first pass complete, so input
	 * refused before it leaves no output at all */
	dem_state_reader_t *rd;
	const dem_profile_opts_t *o;
	const char *from;
	int argc;
	char **args;
	dem_writer_t *w;
	dem_afile_t surf, sat;   /* the tables, written atomically */
	size_t passes, points;
};

static double pfield(const dem_profile_t *p, size_t i, int f)
{
	return f < 6 ? p->sig[6 * i + f] : f < 12 ? p->eps[6 * i + f - 6] : p->ep[i];
}

/* The saturation row of a pass: the field at the surface (the shallowest
 * point), its peak (largest magnitude) and the peak's depth, the depth
 * below the peak where it first changes sign (0: never), and the plastic
 * strain at the surface and its largest value. */
static void saturation_row(FILE *f, const struct result *r, int field)
{
	const dem_profile_t *p = &r->p;
	size_t ipk = 0;
	double ep_max = 0, zero = 0;
	for (size_t i = 0; i < p->n; i++) {
		if (fabs(pfield(p, i, field)) > fabs(pfield(p, ipk, field)))
			ipk = i;
		ep_max = fmax(ep_max, p->ep[i]);
	}
	double pk = pfield(p, ipk, field);
	for (size_t i = ipk + 1; i < p->n && pk != 0; i++) {
		double a = pfield(p, i - 1, field), b = pfield(p, i, field);
		if ((pk < 0 && b >= 0) || (pk > 0 && b <= 0)) {
			zero = a == b ? p->depth[i] : p->depth[i - 1] +
			       (p->depth[i] - p->depth[i - 1]) * a / (a - b);
			break;
		}
	}
	fprintf(f, "%u ", r->pass);
	put(f, pfield(p, 0, field), " ");
	put(f, pk, " ");
	put(f, p->depth[ipk], " ");
	put(f, zero, " ");
	put(f, p->ep[0], " ");
	put(f, ep_max, "\n");
}

static int open_outputs(struct run *u, dem_state_reader_t *r, const dem_profile_opts_t *o,
			const char *from, int argc, char **args, dem_error_t *e)
{
	const struct cmdline *cl = u->cl;
	const dem_header_t *sh = dem_state_header(r);
	dem_header_t h;
	int rc = DEM_OK;

	dem_profile_header(&h);
	/* the state's metadata and provenance, not its record layout */
	for (size_t i = 0; i < sh->nline && !rc; i++) {
		const char *k = sh->line[i].key;
		if (strcmp(k, "record") && strcmp(k, "nodes") && strcmp(k, "elements") && strcmp(k, "grid"))
			rc = dem_header_add(&h, k, "%s", sh->line[i].val);
	}
	rc = rc ? rc : dem_header_add_provenance(&h, PROG, argc, args, 0, 0);
	rc = rc ? rc : dem_header_add(&h, "region", "%.17g %.17g %.17g %.17g",
				      o->lo[0], o->lo[1], o->hi[0], o->hi[1]);
	if (o->bin > 0)
		rc = rc ? rc : dem_header_add(&h, "average", "bins size=%.17g area=%s%s", o->bin, from,
					      o->axisym ? " weight=ring" : "");
	else
		rc = rc ? rc : dem_header_add(&h, "average", "layers area=%s%s", from,
					      o->axisym ? " weight=ring" : "");
	if (rc) {
		dem_header_free(&h);
		return dem_error_nomem(e, "header");
	}
	int flags = (cl->com.binary ? DEM_STREAM_BINARY : 0) | (cl->com.gzip ? DEM_STREAM_GZIP : 0);
	rc = dem_writer_open(&u->w, cl->com.output, &h, flags, e);
	dem_header_free(&h);
	if (rc)
		return rc;
	if (cl->surface) {
		if ((rc = dem_afile_open(&u->surf, cl->surface, "w", e)))
			return rc;
		fprintf(u->surf.f, "# demprofile surface metrics per pass (demprofile(1))\n"
			"# region %.17g %.17g %.17g %.17g m, threshold %.17g m, plastic threshold %.17g\n"
			"# pass time:s indented:- depth_max:m depth_mean:m radius:m ra:m "
			"dimples:- patches:- area:m^2 plastic:-\n",
			o->lo[0], o->lo[1], o->hi[0], o->hi[1], o->threshold, o->ep_threshold);
	}
	if (cl->saturation) {
		const char *unit = u->st->field < 6 ? "Pa" : "-";
		if ((rc = dem_afile_open(&u->sat, cl->saturation, "w", e)))
			return rc;
		fprintf(u->sat.f, "# demprofile saturation table: %s (%s) per pass (demprofile(1))\n"
			"# pass surface:%s peak:%s peak_depth:m zero_depth:m ep_surface:- ep_max:-\n",
			fields[u->st->field], unit, unit, unit);
	}
	return DEM_OK;
}

static int emit(struct run *u, struct result *r, dem_error_t *e)
{
	if (!u->w && open_outputs(u, u->rd, u->o, u->from, u->argc, u->args, e))
		return e->code;
	r->p.pass = (int)r->pass;
	if (dem_profile_write(u->w, &r->p, e))
		return e->code;
	u->passes++;
	u->points += r->p.n;
	const dem_surface_t *s = &r->s;
	if (u->surf.f) {
		FILE *f = u->surf.f;
		fprintf(f, "%u ", r->pass);
		put(f, r->time, " ");
		put(f, s->indented, " ");
		put(f, s->depth_max, " ");
		put(f, s->depth_mean, " ");
		put(f, s->radius, " ");
		put(f, s->ra, " ");
		fprintf(f, "%zu %zu ", s->dimples, s->patches);
		put(f, s->area, " ");
		put(f, s->plastic, "\n");
	}
	if (u->sat.f)
		saturation_row(u->sat.f, r, u->st->field);
	if (u->cl->com.verbose) {
		fprintf(stderr, "%s: pass %u (t = %g s): %zu depth points", PROG, r->pass, r->time, r->p.n);
		if (r->has_surface)
			fprintf(stderr, "; plastic coverage %.4g, indented %.4g, %zu whole dimples of "
				"mean depth %.4g um and radius %.4g mm, deepest %.4g um, Ra %.4g um",
				s->plastic, s->indented, s->dimples, 1e6 * s->depth_mean, 1e3 * s->radius,
				1e6 * s->depth_max, 1e6 * s->ra);
		fputc('\n', stderr);
	}
	return DEM_OK;
}

static int wanted(long sel, unsigned pass)
{
	return sel < 0 || (unsigned long)sel == pass;
}

static int profile_stream(struct run *u, dem_state_reader_t *r, const dem_profile_opts_t *o,
			  dem_cost_t *cost, size_t *frames, dem_error_t *e)
{
	const dem_mesh_t *m = dem_state_mesh(r);
	const long sel = u->cl->pass;
	struct result cur = {0};
	dem_state_frame_t f;
	long first = -1, last = -1, npass = 0;
	int got, rc = DEM_OK, found = 0;
	double tread = 0, tcomp = 0, t = dem_wall();

	*frames = 0;
	while ((got = dem_state_next(r, &f, e)) == 1) {
		tread += dem_wall() - t;
		++*frames;
		if (last >= 0 && f.pass < (unsigned long)last) {
			rc = dem_error_set(e, DEM_EINPUT, "%s: a frame of pass %u after pass %ld: "
					   "passes must not decrease", dem_state_name(r), f.pass, last);
			goto out;
		}
		if (last < 0 || f.pass != (unsigned long)last)
			npass++;
		if (first < 0)
			first = f.pass;
		/* a new pass: the one before is complete */
		if (cur.have && f.pass != cur.pass && sel != PASS_LAST) {
			if ((rc = emit(u, &cur, e)))
				goto out;
			cur.have = 0;
		}
		last = f.pass;
		t = dem_wall();
		if (wanted(sel, f.pass)) {
			found = 1;
			dem_profile_free(&cur.p);
			cur.have = 0;
			if ((rc = dem_profile_compute(m, f.sig, f.eps, f.ep, o, &cur.p, e)))
				goto out;
			cur.has_surface = m->nx > 0;
			if (cur.has_surface && (rc = dem_surface_compute(m, f.u, f.ep, o, &cur.s, e)))
				goto out;
			cur.have = 1;
			cur.pass = f.pass;
			cur.time = f.time;
		}
		tcomp += dem_wall() - t;
		t = dem_wall();
	}
	if (got < 0) {
		rc = e->code;
		goto out;
	}
	if (*frames == 0) {
		rc = dem_error_set(e, DEM_EINPUT, "%s: no frame: the state stream holds the mesh only",
				   dem_state_name(r));
		goto out;
	}
	if (!found) {
		rc = dem_error_set(e, DEM_EINPUT, "%s: no pass %ld in the state stream "
				   "(%ld passes, %ld to %ld)", dem_state_name(r), sel, npass, first, last);
		goto out;
	}
	if (cur.have && (rc = emit(u, &cur, e)))
		goto out;
out:
	dem_profile_free(&cur.p);
	dem_cost_time(cost, "read", tread);
	dem_cost_time(cost, "profile", tcomp);
	return rc;
}

/* The scene's settings with the options' overrides; --dump-scene prints
 * them. */
static int get_settings(const struct cmdline *cl, struct settings *set, dem_error_t *e)
{
	dem_scene_t *scene = NULL;
	int rc = dem_scene_open(&scene, &cl->com, e);

	if (!rc)
		rc = read_scene(scene, set, e);
	if (!rc && cl->com.dump)
		dem_scene_dump(scene, stdout);
	dem_scene_free(scene);
	return rc;
}

/* The state stream's mesh and the region to average over, checked
 * against what the options ask of it. */
static int open_input(struct run *u, dem_profile_opts_t *o, dem_cost_t *cost, dem_error_t *e)
{
	const struct cmdline *cl = u->cl;
	double t = dem_wall();
	int rc;

	u->from = "block";
	if ((rc = dem_state_reader_open(&u->rd, cl->input, e)))
		return rc;
	dem_cost_time(cost, "read", dem_wall() - t);
	const dem_mesh_t *m = dem_state_mesh(u->rd);
	if ((rc = find_region(u->st, u->rd, o, &u->from, e)))
		return rc;
	if (o->bin <= 0 && m->nx <= 0)
		return dem_error_set(e, DEM_EINPUT, "%s: the mesh has no '# grid' (not structured): "
				     "element layers cannot be told; give --bins or --bin-size",
				     dem_state_name(u->rd));
	if (cl->surface && m->nx <= 0)
		return dem_error_set(e, DEM_EINPUT, "%s: the mesh has no '# grid' (not structured): "
				     "no surface metrics (--surface)", dem_state_name(u->rd));
	if (cl->com.verbose)
		fprintf(stderr, "%s: %zu nodes, %zu elements; region x %g to %g m, y %g to %g m "
			"(area from the %s); %s%s\n", PROG, m->nn, m->ne, o->lo[0], o->hi[0], o->lo[1],
			o->hi[1], u->from, o->bin > 0 ? "depth bins" : "element layers",
			o->axisym ? ", axisymmetric (x the radius): weighted by ring" : "");
	u->o = o;
	return DEM_OK;
}

/* Commit the tables and close the profile stream. */
static int close_outputs(struct run *u, dem_cost_t *cost, dem_error_t *e)
{
	double t = dem_wall();
	int rc;

	if ((u->surf.f && (rc = dem_afile_commit(&u->surf, 0, e))) ||
	    (u->sat.f && (rc = dem_afile_commit(&u->sat, 0, e))))
		return rc;
	rc = dem_writer_close(u->w, e);
	u->w = NULL;
	if (rc)
		return rc;
	dem_cost_time(cost, "write", dem_wall() - t);
	return DEM_OK;
}

int main(int argc, char **argv)
{
	struct cmdline cl;
	struct settings set = {0};
	struct run run = {.cl = &cl, .st = &set};
	dem_profile_opts_t o;
	dem_main_t r;
	size_t frames = 0;
	int rc;

	if ((rc = dem_main_start(&r, PROG, argc, argv)))
		return rc;
	if ((rc = parse_cmdline(argc, argv, &cl)) >= 0)
		return dem_main_quit(&r, &cl.com, rc);
	run.argc = r.argc;
	run.args = r.args;
	if (!(rc = get_settings(&cl, &set, &r.e)) && !cl.com.dump &&
	    !(rc = open_input(&run, &o, &r.cost, &r.e)) &&
	    !(rc = profile_stream(&run, run.rd, &o, &r.cost, &frames, &r.e)) &&
	    !(rc = close_outputs(&run, &r.cost, &r.e))) {
		const dem_mesh_t *m = dem_state_mesh(run.rd);
		dem_cost_count(&r.cost, "frames", (double)frames);
		dem_cost_count(&r.cost, "passes", (double)run.passes);
		dem_cost_count(&r.cost, "points", (double)run.points);
		dem_cost_count(&r.cost, "elements", (double)m->ne);
		dem_cost_count(&r.cost, "nodes", (double)m->nn);
	}
	if (rc) {
		dem_writer_abort(run.w);
		dem_afile_abort(&run.surf);
		dem_afile_abort(&run.sat);
	}
	dem_state_reader_close(run.rd);
	return dem_main_end(&r, &cl.com, rc);
}
