/* dempack - make packings of disks and spheres, and shot streams.
 *
 *   dempack random [options]     N objects placed at random, overlaps allowed,
 *                                in a box sized for a target density (Ch. 2.5)
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
#include "pack/random.h"

#define PROG "dempack"

enum { OPT_DIM = DEM_OPT_PROGRAM, OPT_DENSITY, OPT_LAW, OPT_RMIN, OPT_LAMBDA,
       OPT_ASPECT };

static const dem_opt_t options[] = {
	{"dim", OPT_DIM, "D", "dimension: 2 (disks) or 3 (spheres); default 2"},
	{"number", 'n', "N", "number of objects; default 1000"},
	{"density", OPT_DENSITY, "RHO", "packing density in (0, 1]; default 0.6"},
	{"law", OPT_LAW, "LAW", "radius law: mono, urd, nrd or lnrd; default urd"},
	{"rmin", OPT_RMIN, "R", "smallest radius, with a unit if wanted (1 mm); default 1 m"},
	{"lambda", OPT_LAMBDA, "L", "size ratio Rmax/Rmin, at least 1; default 1"},
	{"aspect", OPT_ASPECT, "AX:AY[:AZ]", "domain side ratios; default 1:1[:1]"},
	DEM_OPTS_COMMON,
	{0}
};

static const char usage[] =
	"Usage: dempack random [OPTION]...\n";
static const char purpose[] =
	"Make a packing of disks or spheres and write it as a particle stream.\n"
	"\n"
	"Methods:\n"
	"  random    N objects uniformly at random in a box sized for the target\n"
	"            density; overlaps allowed (the detection test sets of Ch. 2.5)";
static const char epilogue[] =
	"Example:\n"
	"  dempack random --dim 2 -n 1000000 --density 0.6 --lambda 10 --law urd --seed 1 -b\n"
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
};

static void cmdline_free(struct cmdline *cl)
{
	free(cl->ov);
	free(cl->aspect);
}

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
	cl->ov = malloc((size_t)argc * sizeof *cl->ov);
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
		case OPT_ASPECT: {
			/* "2:1" -> "2, 1", which the scene reads as a vector */
			free(cl->aspect);
			cl->aspect = strdup(optarg);
			if (!cl->aspect)
				return DEM_EIO;
			for (char *p = cl->aspect; *p; p++)
				if (*p == ':')
					*p = ',';
			add_override(cl, "pack.aspect", cl->aspect, "--aspect");
			break;
		}
		default:
			break;
		}
	}
	if (done < 0) {
		if (optind < argc)
			cl->method = argv[optind++];
		if (!cl->method && !cl->dump)
			dem_cli_error(&c, "no method given (random)");
		else if (cl->method && strcmp(cl->method, "random") != 0)
			dem_cli_error(&c, "unknown method '%s' (this version has: random)", cl->method);
		if (optind < argc)
			dem_cli_error(&c, "unexpected argument '%s'", argv[optind]);
		if (dem_cli_finish(&c))
			done = DEM_EUSAGE;
	}
	dem_cli_free(&c);
	return done;
}

/* The pack: section, resolved. */
static int read_scene(dem_scene_t *s, dem_random_spec_t *sp, dem_error_t *e)
{
	static const char *const methods[] = {"random", NULL};
	static const char *const sections[] = {"pack", NULL};
	long dim, n;
	int method, law;
	double rmin, lambda;
	const double one[3] = {1, 1, 1};

	if (dem_scene_choice(s, "pack.method", methods, 0, &method, e) ||
	    dem_scene_int(s, "pack.dim", 2, 2, 3, &dim, e) ||
	    dem_scene_int(s, "pack.n", 1000, 0, 4294967295L, &n, e) ||
	    dem_scene_quantity(s, "pack.density", DEM_DIM_NONE, 0.6, DEM_SCENE_GT0, 1, &sp->density, e) ||
	    dem_scene_choice(s, "pack.radius.law", dem_radius_names, DEM_RADIUS_URD, &law, e) ||
	    dem_scene_quantity(s, "pack.radius.min", DEM_DIM_LENGTH, 1, DEM_SCENE_GT0, HUGE_VAL, &rmin, e) ||
	    dem_scene_quantity(s, "pack.radius.lambda", DEM_DIM_NONE, 1, 1, 1e9, &lambda, e) ||
	    dem_scene_vector(s, "pack.aspect", DEM_DIM_NONE, (int)dim, one, DEM_SCENE_GT0, 1e9, sp->aspect, e))
		return e->code;
	sp->dim = (int)dim;
	sp->n = (size_t)n;
	sp->law = (dem_radius_law_t){(dem_radius_kind_t)law, rmin, rmin * lambda};
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

int main(int argc, char **argv)
{
	struct cmdline cl;
	dem_error_t e = {0};
	dem_scene_t *scene = NULL;
	dem_writer_t *w = NULL;
	dem_random_spec_t sp;
	dem_cost_t cost;
	int rc;

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
	if ((rc = read_scene(scene, &sp, &e)))
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
	dem_header_init(&h, "particles", 1, sp.dim);
	for (int d = 0; d < sp.dim; d++)
		dem_header_add_col(&h, axes[d], DEM_F64, "m");
	dem_header_add_col(&h, "r", DEM_F64, "m");
	dem_header_add_provenance(&h, PROG, argc, args, 1, cl.seed);
	dem_header_add(&h, "seed", "%lu", cl.seed);
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
