/* dempack - make packings of disks and spheres, and shot streams.
 *
 *   dempack random [options]     N objects placed at random, overlaps allowed,
 *                                in a box sized for a target density (Ch. 2.5)
 *   dempack front [options]      disks filling a rectangle by an advancing
 *                                front, closed or open form (Ch. 5.2)
 *
 * Writes a particle stream (x y [z] r) on standard output or to -o FILE.
 * The scene's pack: section gives the defaults; options override it.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "core/cli.h"
#include "core/cost.h"
#include "core/fmt.h"
#include "core/radius.h"
#include "core/rng.h"
#include "io/scene.h"
#include "io/stream.h"
#include "pack/front.h"
#include "pack/random.h"

#define PROG "dempack"

enum { OPT_DIM = DEM_OPT_PROGRAM, OPT_DENSITY, OPT_LAW, OPT_RMIN, OPT_LAMBDA,
       OPT_ASPECT, OPT_FORM, OPT_DOMAIN, OPT_CHECK_LIMIT, OPT_GRAVITY };

enum { METHOD_RANDOM, METHOD_FRONT };
static const char *const methods[] = {"random", "front", NULL};

static const dem_opt_t options[] = {
	{"dim", OPT_DIM, "D", "dimension: 2 (disks) or 3 (spheres); default 2"},
	{"number", 'n', "N", "number of objects; default 1000"},
	{"density", OPT_DENSITY, "RHO", "packing density in (0, 1]; default 0.6"},
	{"law", OPT_LAW, "LAW", "radius law: mono, urd, nrd or lnrd; default urd"},
	{"rmin", OPT_RMIN, "R", "smallest radius, with a unit if wanted (1 mm); default 1 m"},
	{"lambda", OPT_LAMBDA, "L", "size ratio Rmax/Rmin, at least 1; default 1"},
	{"aspect", OPT_ASPECT, "AX:AY[:AZ]", "domain side ratios; default 1:1[:1]"},
	{"form", OPT_FORM, "FORM", "front: closed (from the centre) or open (from the bottom); default open"},
	{"domain", OPT_DOMAIN, "XLO:YLO:XHI:YHI", "front: the rectangle to fill; default 0:0:50:50 (m)"},
	{"check-limit", OPT_CHECK_LIMIT, "K", "front: check at most K front disks each way; default 0, no limit"},
	{"gravity", OPT_GRAVITY, NULL, "front, open form: each disk rests stably under gravity (-y)"},
	DEM_OPTS_COMMON,
	{0}
};

static const char usage[] =
	"Usage: dempack random [OPTION]...\n"
	"  or:  dempack front [OPTION]...\n";
static const char purpose[] =
	"Make a packing of disks or spheres and write it as a particle stream.\n"
	"\n"
	"Methods:\n"
	"  random    N objects uniformly at random in a box sized for the target\n"
	"            density; overlaps allowed (the detection test sets of Ch. 2.5)\n"
	"  front     disks filling a rectangle densely and without overlap by an\n"
	"            advancing front, closed or open form (Ch. 5.2); disks not wholly\n"
	"            inside are culled; the density reached is in the header";
static const char epilogue[] =
	"Example:\n"
	"  dempack random --dim 2 -n 1000000 --density 0.6 --lambda 10 --law urd --seed 1 -b\n"
	"  dempack front --domain 0:0:1500:1500 --rmin 0.5 --lambda 2 --seed 1 -b\n"
	"\nSee dempack(1), dem-scene(5) and dem-streams(5).\n";

struct override {
	const char *key, *text, *origin;
};

struct cmdline {
	const char *method;
	const char *scene, *output;
	int binary, gzip, have_seed, dump, verbose, quiet;
	unsigned long seed;
	struct override *ov;    /* scene keys set by options, in order */
	int nov;
	char *aspect;           /* --aspect rewritten as a scene vector */
	char *domain;           /* --domain likewise */
	unsigned long given;    /* method options given: bit (key - OPT_DIM) */
};

static void cmdline_free(struct cmdline *cl)
{
	free(cl->ov);
	free(cl->aspect);
	free(cl->domain);
}

/* "a:b:c" -> "a, b, c", which the scene reads as a vector; NULL without
 * memory. */
static char *colon_vector(char **buf, const char *text)
{
	free(*buf);
	if (!(*buf = strdup(text)))
		return NULL;
	for (char *p = *buf; *p; p++)
		if (*p == ':')
			*p = ',';
	return *buf;
}

/* The method options that only one method reads; given to the other
 * they are usage errors. */
static const struct {
	int key, method;
	const char *name;
} method_opts[] = {
	{OPT_DIM, METHOD_RANDOM, "--dim"}, {'n', METHOD_RANDOM, "--number"},
	{OPT_DENSITY, METHOD_RANDOM, "--density"}, {OPT_ASPECT, METHOD_RANDOM, "--aspect"},
	{OPT_FORM, METHOD_FRONT, "--form"}, {OPT_DOMAIN, METHOD_FRONT, "--domain"},
	{OPT_CHECK_LIMIT, METHOD_FRONT, "--check-limit"}, {OPT_GRAVITY, METHOD_FRONT, "--gravity"},
};
#define NMETHOD_OPTS (sizeof method_opts / sizeof method_opts[0])

static void add_override(struct cmdline *cl, const char *key, const char *text,
			 const char *origin)
{
	cl->ov[cl->nov++] = (struct override){key, text, origin};
}

/* Returns -1 to go on, or the exit code (help, version, usage error). */
static int parse_cmdline(int argc, char **argv, struct cmdline *cl)
{
	dem_cli_t c;
	int k, done = -1;

	memset(cl, 0, sizeof *cl);
	cl->ov = malloc(((size_t)argc + 1) * sizeof *cl->ov);   /* options and the method */
	if (!cl->ov || dem_cli_init(&c, PROG, options) != 0)
		return DEM_EIO;
	while ((k = dem_cli_next(&c, argc, argv)) != -1) {
		switch (k) {
		case 's': cl->scene = optarg; break;
		case 'o': cl->output = optarg; break;
		case 'b': cl->binary = 1; break;
		case 'z': cl->gzip = 1; break;
		case 'v': cl->verbose++; break;
		case 'q': cl->quiet = 1; break;
		case DEM_OPT_SEED:
			if (dem_cli_ulong(&c, "--seed", optarg, 0, 0xffffffffUL, &cl->seed) == 0)
				cl->have_seed = 1;
			break;
		case DEM_OPT_ACCURACY:
			if (strcmp(optarg, "coarse") && strcmp(optarg, "normal") && strcmp(optarg, "fine"))
				dem_cli_error(&c, "--accuracy: '%s': expected coarse, normal or fine", optarg);
			break;      /* random sets have no accuracy knob */
		case DEM_OPT_DUMP_SCENE: cl->dump = 1; break;
		case 'h':
			dem_cli_help(&c, stdout, usage, purpose, epilogue);
			done = 0;
			break;
		case DEM_OPT_VERSION:
			dem_cli_version(&c);
			done = 0;
			break;
		case OPT_DIM: add_override(cl, "pack.dim", optarg, "--dim"); break;
		case 'n': add_override(cl, "pack.n", optarg, "--number"); break;
		case OPT_DENSITY: add_override(cl, "pack.density", optarg, "--density"); break;
		case OPT_LAW: add_override(cl, "pack.radius.law", optarg, "--law"); break;
		case OPT_RMIN: add_override(cl, "pack.radius.min", optarg, "--rmin"); break;
		case OPT_LAMBDA: add_override(cl, "pack.radius.lambda", optarg, "--lambda"); break;
		case OPT_ASPECT:
			if (!colon_vector(&cl->aspect, optarg))
				return DEM_EIO;
			add_override(cl, "pack.aspect", cl->aspect, "--aspect");
			break;
		case OPT_FORM: add_override(cl, "pack.form", optarg, "--form"); break;
		case OPT_DOMAIN:
			if (!colon_vector(&cl->domain, optarg))
				return DEM_EIO;
			add_override(cl, "pack.domain", cl->domain, "--domain");
			break;
		case OPT_CHECK_LIMIT: add_override(cl, "pack.check_limit", optarg, "--check-limit"); break;
		case OPT_GRAVITY: add_override(cl, "pack.gravity", "true", "--gravity"); break;
		default:
			break;
		}
		for (size_t i = 0; i < NMETHOD_OPTS; i++)
			if (k == method_opts[i].key)
				cl->given |= 1UL << i;
	}
	if (done < 0) {
		if (optind < argc)
			cl->method = argv[optind++];
		int m = -1;
		for (int i = 0; cl->method && methods[i]; i++)
			if (strcmp(cl->method, methods[i]) == 0)
				m = i;
		if (!cl->method && !cl->dump)
			dem_cli_error(&c, "no method given (random or front)");
		else if (cl->method && m < 0)
			dem_cli_error(&c, "unknown method '%s' (this version has: random, front)", cl->method);
		for (size_t i = 0; m >= 0 && i < NMETHOD_OPTS; i++)
			if ((cl->given >> i & 1) && method_opts[i].method != m)
				dem_cli_error(&c, "%s: not an option of method %s", method_opts[i].name, methods[m]);
		if (m >= 0)     /* the method typed wins over the scene's */
			add_override(cl, "pack.method", cl->method, cl->method);
		if (optind < argc)
			dem_cli_error(&c, "unexpected argument '%s'", argv[optind]);
		if (dem_cli_finish(&c))
			done = DEM_EUSAGE;
	}
	dem_cli_free(&c);
	return done;
}

/* The front method's keys of the pack: section. */
static int read_front(dem_scene_t *s, dem_front_spec_t *fp, dem_error_t *e)
{
	static const double dom0[4] = {0, 0, 50, 50};
	double dom[4];
	long limit;
	int form;

	if (dem_scene_choice(s, "pack.form", dem_front_form_names, DEM_FRONT_OPEN, &form, e) ||
	    dem_scene_vector(s, "pack.domain", DEM_DIM_LENGTH, 4, dom0, -HUGE_VAL, HUGE_VAL, dom, e) ||
	    dem_scene_int(s, "pack.check_limit", 0, 0, 1000000000L, &limit, e) ||
	    dem_scene_bool(s, "pack.gravity", 0, &fp->gravity, e))
		return e->code;
	if (!(dom[0] < dom[2] && dom[1] < dom[3]))
		return dem_scene_error(s, "pack.domain", e,
				       "expected [xlo, ylo, xhi, yhi] with xlo < xhi and ylo < yhi");
	if (fp->gravity && form != DEM_FRONT_OPEN)
		return dem_scene_error(s, "pack.gravity", e,
				       "gravity needs the open form (Ch. 5.2.3)");
	fp->form = (dem_front_form_t)form;
	fp->lo[0] = dom[0];
	fp->lo[1] = dom[1];
	fp->hi[0] = dom[2];
	fp->hi[1] = dom[3];
	fp->check_limit = (int)limit;
	return DEM_OK;
}

/* The radius law, read by both methods. */
static int read_law(dem_scene_t *s, dem_radius_law_t *law, dem_error_t *e)
{
	double rmin, lambda;
	int kind;

	if (dem_scene_choice(s, "pack.radius.law", dem_radius_names, DEM_RADIUS_URD, &kind, e) ||
	    dem_scene_quantity(s, "pack.radius.min", DEM_DIM_LENGTH, 1, DEM_SCENE_GT0, HUGE_VAL, &rmin, e) ||
	    dem_scene_quantity(s, "pack.radius.lambda", DEM_DIM_NONE, 1, 1, 1e9, &lambda, e))
		return e->code;
	*law = (dem_radius_law_t){(dem_radius_kind_t)kind, rmin, rmin * lambda};
	return DEM_OK;
}

/* The pack: section, resolved: the method, then its keys. */
static int read_scene(dem_scene_t *s, int *method, dem_random_spec_t *sp,
		      dem_front_spec_t *fp, dem_error_t *e)
{
	static const char *const sections[] = {"pack", NULL};
	long dim, n;
	const double one[3] = {1, 1, 1};

	if (dem_scene_choice(s, "pack.method", methods, METHOD_RANDOM, method, e))
		return e->code;
	if (*method == METHOD_FRONT) {
		if (read_law(s, &fp->law, e) || read_front(s, fp, e))
			return e->code;
		return dem_scene_check(s, sections, e);
	}
	if (dem_scene_int(s, "pack.dim", 2, 2, 3, &dim, e) ||
	    dem_scene_int(s, "pack.n", 1000, 0, 4294967295L, &n, e) ||
	    dem_scene_quantity(s, "pack.density", DEM_DIM_NONE, 0.6, DEM_SCENE_GT0, 1, &sp->density, e) ||
	    read_law(s, &sp->law, e) ||
	    dem_scene_vector(s, "pack.aspect", DEM_DIM_NONE, (int)dim, one, DEM_SCENE_GT0, 1e9, sp->aspect, e))
		return e->code;
	sp->dim = (int)dim;
	sp->n = (size_t)n;
	return dem_scene_check(s, sections, e);
}

struct emit_ctx {
	dem_writer_t *w;
	dem_error_t *e;
	int dim;
};

static int emit(void *ctx, const double *x, double r)
{
	struct emit_ctx *c = ctx;
	double row[4];
	for (int d = 0; d < c->dim; d++)
		row[d] = x[d];
	row[c->dim] = r;
	return dem_writer_row(c->w, row, c->e);
}

/* dempack front: the writer opens at the first disk (or at the end when
 * none is kept), once the statistics are complete, so the header carries
 * the density reached. */
struct front_out {
	dem_writer_t *w;
	dem_header_t *h;
	const dem_front_stats_t *st;
	const char *path;
	int flags;
	dem_error_t *e;
	double t_packed;        /* when the packing was done (cost line) */
};

static int front_open(struct front_out *o)
{
	char rho[32];
	o->t_packed = dem_wall();
	dem_fmt_double(rho, o->st->density);
	dem_header_set(o->h, "density", "%s", rho);
	return dem_writer_open(&o->w, o->path, o->h, o->flags, o->e);
}

static int front_emit(void *ctx, const double *x, double r)
{
	struct front_out *o = ctx;
	double row[3] = {x[0], x[1], r};
	int rc;

	if (!o->w && (rc = front_open(o)))
		return rc;
	return dem_writer_row(o->w, row, o->e);
}

/* Pack by the advancing front and write the kept disks; h has the common
 * lines already. */
static int write_front(const dem_front_spec_t *fp, const struct cmdline *cl,
		       dem_header_t *h, dem_cost_t *cost, dem_error_t *e)
{
	char buf[4][32], rmin[32], lambda[32];
	dem_front_stats_t st;
	int rc;

	dem_fmt_double(rmin, fp->law.rmin);
	dem_fmt_double(lambda, fp->law.rmax / fp->law.rmin);
	dem_header_add(h, "method", "front form=%s law=%s rmin=%s lambda=%s check_limit=%d gravity=%s",
		       dem_front_form_names[fp->form], dem_radius_names[fp->law.kind], rmin,
		       lambda, fp->check_limit, fp->gravity ? "true" : "false");
	dem_fmt_double(buf[0], fp->lo[0]);
	dem_fmt_double(buf[1], fp->lo[1]);
	dem_fmt_double(buf[2], fp->hi[0]);
	dem_fmt_double(buf[3], fp->hi[1]);
	dem_header_set(h, "domain", "%s %s %s %s", buf[0], buf[1], buf[2], buf[3]);

	gsl_rng *rng = dem_rng_derive(cl->seed, 0);
	if (!rng)
		return dem_error_nomem(e, "random generator");
	struct front_out o = {NULL, h, &st, cl->output,
			      (cl->binary ? DEM_STREAM_BINARY : 0) | (cl->gzip ? DEM_STREAM_GZIP : 0), e, 0};
	double t0 = dem_wall();
	rc = dem_pack_front(fp, rng, front_emit, &o, &st, e);
	gsl_rng_free(rng);
	if (rc == DEM_OK && !o.w)
		rc = front_open(&o);
	if (rc == DEM_OK) {
		rc = dem_writer_close(o.w, e);
		o.w = NULL;
	}
	if (rc) {
		dem_writer_abort(o.w);
		return rc;
	}
	dem_cost_time(cost, "pack", o.t_packed - t0);
	dem_cost_time(cost, "write", dem_wall() - o.t_packed);
	dem_cost_count(cost, "objects", (double)st.kept);
	dem_cost_count(cost, "placed", (double)st.placed);
	dem_cost_count(cost, "density", st.density);
	dem_cost_count(cost, "failed", (double)st.failed);
	return DEM_OK;
}

int main(int argc, char **argv)
{
	struct cmdline cl;
	dem_error_t e = {0};
	dem_scene_t *scene = NULL;
	dem_writer_t *w = NULL;
	dem_random_spec_t sp;
	dem_front_spec_t fp = {0};
	dem_cost_t cost;
	int rc, method;

	dem_cost_start(&cost);
	gsl_set_error_handler_off();
	/* getopt reorders argv; the provenance keeps the order typed */
	char **args = malloc(((size_t)argc + 1) * sizeof *args);
	if (!args)
		return DEM_EIO;
	memcpy(args, argv, ((size_t)argc + 1) * sizeof *args);
	if ((rc = parse_cmdline(argc, argv, &cl)) >= 0) {
		free(args);
		cmdline_free(&cl);
		return rc;
	}
	if ((rc = dem_scene_load(&scene, cl.scene, &e)))
		goto fail;
	for (int i = 0; i < cl.nov; i++)
		if ((rc = dem_scene_override(scene, cl.ov[i].key, cl.ov[i].text, cl.ov[i].origin, &e)))
			goto fail;
	if ((rc = read_scene(scene, &method, &sp, &fp, &e)))
		goto fail;
	if (cl.dump) {
		dem_scene_dump(scene, stdout);
		dem_scene_free(scene);
		free(args);
		cmdline_free(&cl);
		return dem_cli_close_stdout(PROG);
	}

	gsl_rng *probe = dem_rng_new(&cl.have_seed, &cl.seed);  /* draws a seed if none */
	gsl_rng_free(probe);

	/* The domain depends on the radii drawn: size it first, then write. */
	dem_header_t h;
	const char *axes[] = {"x", "y", "z"};
	int dim = method == METHOD_FRONT ? 2 : sp.dim;
	dem_header_init(&h, "particles", 1, dim);
	for (int d = 0; d < dim; d++)
		dem_header_add_col(&h, axes[d], DEM_F64, "m");
	dem_header_add_col(&h, "r", DEM_F64, "m");
	dem_header_add_provenance(&h, PROG, argc, args, 1, cl.seed);
	dem_header_add(&h, "seed", "%lu", cl.seed);
	if (method == METHOD_FRONT) {
		if ((rc = write_front(&fp, &cl, &h, &cost, &e)))
			goto fail_h;
		goto done;
	}
	char rmin[32], lambda[32], rho[32];
	dem_fmt_double(rmin, sp.law.rmin);
	dem_fmt_double(lambda, sp.law.rmax / sp.law.rmin);
	dem_fmt_double(rho, sp.density);
	dem_header_add(&h, "method", "random law=%s rmin=%s lambda=%s density=%s",
		       dem_radius_names[sp.law.kind], rmin, lambda, rho);

	double hi[3] = {0, 0, 0};
	if ((rc = dem_pack_random_domain(&sp, cl.seed, hi, &e)))
		goto fail_h;
	{
		char buf[160];
		int n = 0;
		for (int d = 0; d < sp.dim; d++)
			n += snprintf(buf + n, sizeof buf - (size_t)n, "%s0", d ? " " : "");
		for (int d = 0; d < sp.dim; d++) {
			buf[n++] = ' ';
			n += dem_fmt_double(buf + n, hi[d]);
		}
		dem_header_set(&h, "domain", "%s", buf);
	}
	int flags = (cl.binary ? DEM_STREAM_BINARY : 0) | (cl.gzip ? DEM_STREAM_GZIP : 0);
	if ((rc = dem_writer_open(&w, cl.output, &h, flags, &e)))
		goto fail_h;
	double t0 = dem_wall();
	struct emit_ctx ctx = {w, &e, sp.dim};
	if ((rc = dem_pack_random(&sp, cl.seed, hi, emit, &ctx, &e)))
		goto fail_h;
	if ((rc = dem_writer_close(w, &e))) {
		w = NULL;
		goto fail_h;
	}
	w = NULL;
	dem_cost_time(&cost, "pack", dem_wall() - t0);
	dem_cost_count(&cost, "objects", (double)sp.n);
done:
	dem_header_free(&h);
	dem_scene_free(scene);
	free(args);
	cmdline_free(&cl);
	if (!cl.output && (rc = dem_cli_close_stdout(PROG)))
		return rc;
	dem_cost_print(&cost, PROG, stderr);
	return 0;
fail_h:
	dem_header_free(&h);
fail:
	fprintf(stderr, "%s: %s\n", PROG, e.msg);
	if (rc == DEM_EUSAGE)
		fprintf(stderr, "Try '%s --help' for more information.\n", PROG);
	dem_writer_abort(w);
	dem_scene_free(scene);
	free(args);
	cmdline_free(&cl);
	return rc;
}
