/* dempack - make packings of disks and spheres, and shot streams.
 *
 *   dempack random [options]     N objects placed at random, overlaps allowed,
 *                                in a box sized for a target density (Ch. 2.5)
 *   dempack front [options]      disks filling a rectangle or (open form) a
 *                                polygon by an advancing front (Ch. 5.2)
 *   dempack compress [options]   spheres filling a box, a cylinder or a convex
 *                                polyhedron densely and without overlap by
 *                                compression (Ch. 6) and relaxation
 *   dempack shots [options]      the impacts of a peening job, pass by pass:
 *                                an offset n x n grid (Ch. 8.6) or random
 *                                positions up to a coverage (Ch. 7.1.3)
 *
 * Writes a particle stream (x y [z] r), or for shots a shot stream, on
 * standard output or to -o FILE.  The scene's pack: section (and shot: for
 * shots) gives the defaults; options override it.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/afile.h"
#include "core/cli.h"
#include "core/consts.h"
#include "core/cost.h"
#include "core/fmt.h"
#include "core/radius.h"
#include "core/rng.h"
#include "body/frames.h"
#include "io/scene.h"
#include "io/stream.h"
#include "io/vtk.h"
#include "pack/compress.h"
#include "pack/front.h"
#include "pack/random.h"
#include "pack/shots.h"

#define PROG "dempack"

enum { OPT_DIM = DEM_OPT_PROGRAM, OPT_DENSITY, OPT_LAW, OPT_RMIN, OPT_LAMBDA,
       OPT_ASPECT, OPT_FORM, OPT_DOMAIN, OPT_POLYGON, OPT_CHECK_LIMIT, OPT_GRAVITY, OPT_VTK,
       OPT_PATTERN, OPT_AREA, OPT_GRID, OPT_PASSES, OPT_COVERAGE, OPT_PER_PASS,
       OPT_SEPARATION, OPT_DIMPLE, OPT_SPEED, OPT_ANGLE, OPT_SHOT_RADIUS,
       OPT_BOX, OPT_CYLINDER, OPT_PLANES, OPT_NO_RELAX, OPT_TOLERANCE, OPT_SHAKES, OPT_CONE,
       OPT_STAGES, OPT_SHAPE, OPT_SIDES, OPT_RATIO_LAW, OPT_RATIO_MIN, OPT_RATIO_MAX };

enum { METHOD_RANDOM, METHOD_FRONT, METHOD_SHOTS, METHOD_COMPRESS };
static const char *const methods[] = {"random", "front", "shots", "compress", NULL};

static const dem_opt_t options[] = {
	{"dim", OPT_DIM, "D", "dimension: 2 (disks) or 3 (spheres); default 2"},
	{"number", 'n', "N", "number of objects; default 1000 (compress: at most N spheres; default 0, no limit)"},
	{"density", OPT_DENSITY, "RHO", "packing density in (0, 1]; default 0.6"},
	{"law", OPT_LAW, "LAW", "radius law: mono, urd, nrd or lnrd; default urd"},
	{"rmin", OPT_RMIN, "R", "smallest radius, with a unit if wanted (1 mm); default 1 m"},
	{"lambda", OPT_LAMBDA, "L", "size ratio Rmax/Rmin, at least 1; default 1"},
	{"aspect", OPT_ASPECT, "AX:AY[:AZ]", "domain side ratios; default 1:1[:1]"},
	{"form", OPT_FORM, "FORM", "front: closed (from the centre) or open (from the bottom); default open"},
	{"domain", OPT_DOMAIN, "XLO:YLO:XHI:YHI", "front: the rectangle to fill; default 0:0:50:50 (m)"},
	{"polygon", OPT_POLYGON, "X:Y:X:Y:X:Y[:X:Y]", "front, open form: fill this simple polygon (3 or more vertices, convex or concave) instead of --domain"},
	{"vtk", OPT_VTK, "FILE", "front (disks), compress: also write the packing to FILE as legacy VTK points with a radius scalar (ParaView)"},
	{"check-limit", OPT_CHECK_LIMIT, "K", "front: check at most K front disks each way; default 0, no limit"},
	{"gravity", OPT_GRAVITY, NULL, "front, open form: each disk rests stably under gravity (-y)"},
	{"shape", OPT_SHAPE, "SHAPE", "front: disk, polygon or ellipse (Ch. 5.3-5.4; a body stream); default disk"},
	{"sides", OPT_SIDES, "N", "front, polygon: sides of each polygon, 3 to 64; default 6"},
	{"ratio-law", OPT_RATIO_LAW, "LAW", "front, polygon or ellipse: aspect ratio law (mono, urd, nrd, lnrd); default urd"},
	{"ratio-min", OPT_RATIO_MIN, "A", "front, polygon or ellipse: smallest aspect ratio a/b, at least 1; default 1"},
	{"ratio-max", OPT_RATIO_MAX, "A", "front, polygon or ellipse: largest aspect ratio a/b; default the smallest"},
	{"box", OPT_BOX, "XLO:YLO:ZLO:XHI:YHI:ZHI", "compress: the box to fill (with --planes: their bounding box); default 0:0:0:20:20:20 (m)"},
	{"cylinder", OPT_CYLINDER, "CX:CY:R:ZLO:ZHI", "compress: fill the cylinder of radius R about the vertical axis (CX, CY) from ZLO to ZHI"},
	{"planes", OPT_PLANES, "NX:NY:NZ:D[:NX:NY:NZ:D]", "compress: cut the box or cylinder by the half-spaces NX x + NY y + NZ z >= D (a convex polyhedron); 4 numbers a plane"},
	{"no-relax", OPT_NO_RELAX, NULL, "compress: the thesis's stages only (Boxes 6.1-6.4), no relaxation under gravity"},
	{"tolerance", OPT_TOLERANCE, "TAU", "compress: tau of the energy test Eq. 6.8; default by --accuracy (1e-3)"},
	{"shakes", OPT_SHAKES, "N", "compress: N_s shakes per round of Box 6.2; default 5"},
	{"cone", OPT_CONE, "B", "compress: beta-bar of Eq. 6.9, the cone of random compression; default 0.5"},
	{"stages", OPT_STAGES, "FILE", "compress: write each stage (phase, batch, spheres, density, seconds) to FILE as a table"},
	{"pattern", OPT_PATTERN, "P", "shots: grid (offset n x n per pass) or random; default grid"},
	{"area", OPT_AREA, "AX:AY", "shots: sides of the impact area; default 5.6mm:5.6mm"},
	{"grid", OPT_GRID, "N", "shots, grid: N x N shots per pass; default 4"},
	{"passes", OPT_PASSES, "N", "shots: number of passes; default 32"},
	{"coverage", OPT_COVERAGE, "PCT", "shots, random: target coverage in percent (100 = 98 % dimpled)"},
	{"per-pass", OPT_PER_PASS, "N", "shots, random: shots per pass; default 8"},
	{"separation", OPT_SEPARATION, "F", "shots, random: centres of a pass F (ri + rj) apart; default 1"},
	{"dimple-radius", OPT_DIMPLE, "L", "shots: dimple radius for coverage (needed with --coverage)"},
	{"speed", OPT_SPEED, "V", "shots: impact speed; default 46.5 m/s"},
	{"angle", OPT_ANGLE, "A", "shots: impingement angle to the surface; default 90 deg"},
	{"shot-radius", OPT_SHOT_RADIUS, "R", "shots: shot radius; default 0.7 mm (S550)"},
	DEM_OPTS_COMMON,
	{0}
};

static const char usage[] =
	"Usage: dempack random [OPTION]...\n"
	"  or:  dempack front [OPTION]...\n"
	"  or:  dempack shots [OPTION]...\n"
	"  or:  dempack compress [OPTION]...\n";
static const char purpose[] =
	"Make a packing of disks or spheres and write it as a particle stream.\n"
	"\n"
	"Methods:\n"
	"  random    N objects uniformly at random in a box sized for the target\n"
	"            density; overlaps allowed (the detection test sets of Ch. 2.5)\n"
	"  front     disks filling a rectangle densely and without overlap by an\n"
	"            advancing front, closed or open form (Ch. 5.2), or with the open\n"
	"            form any simple polygon; disks not wholly inside are culled; the\n"
	"            density reached is in the header\n"
	"  compress  spheres filling a box, a vertical cylinder or a convex polyhedron\n"
	"            without overlap: random loose start, global, random and shaking\n"
	"            compression and refilling from the lid (Ch. 6), each batch\n"
	"            relaxed under gravity as frictionless spheres; the density\n"
	"            reached is in the header\n"
	"  shots     the impacts of a peening job as a shot stream, pass by pass: an\n"
	"            n x n grid offset in every pass (Ch. 8.6) or random positions\n"
	"            until a target coverage (Ch. 7.1.3)";
static const char epilogue[] =
	"Example:\n"
	"  dempack random --dim 2 -n 1000000 --density 0.6 --lambda 10 --law urd --seed 1 -b\n"
	"  dempack front --domain 0:0:1500:1500 --rmin 0.5 --lambda 2 --seed 1 -b\n"
	"  dempack front --polygon 0:0:2:0:2:1:1:1:1:2:0:2 --rmin 0.02 --gravity --vtk l.vtk\n"
	"  dempack compress --cylinder 0:0:0.4mm:0:1.6mm --rmin 0.01mm --lambda 2 --seed 1\n"
	"  dempack shots --grid 4 --passes 32 --area 5.6mm:5.6mm --speed 46.5\n"
	"  dempack shots --pattern random --coverage 200 --dimple-radius 0.4mm --seed 1\n"
	"\nSee dempack(1), dem-scene(5) and dem-streams(5).\n";

struct cmdline {
	dem_common_t com;
	const char *method;
	const char *vtk;        /* --vtk FILE, or NULL */
	const char *stages;     /* --stages FILE, or NULL */
};

/* The method options: the scene key each sets, and the methods that read
 * it (a bit per method); given to another method they are usage errors.
 * Shots take their radius law from the scene's shot: section, so --law,
 * --rmin and --lambda (the pack.radius keys) are not theirs. */
#define M_RANDOM (1u << METHOD_RANDOM)
#define M_FRONT (1u << METHOD_FRONT)
#define M_SHOTS (1u << METHOD_SHOTS)
#define M_COMPRESS (1u << METHOD_COMPRESS)
static const struct method_opt {
	int key;
	unsigned methods;
	const char *name, *scene_key;
	int vector;             /* typed "a:b:c" for a vector key */
} method_opts[] = {
	{OPT_DIM, M_RANDOM, "--dim", "pack.dim", 0},
	{'n', M_RANDOM | M_COMPRESS, "--number", "pack.n", 0},
	{OPT_DENSITY, M_RANDOM, "--density", "pack.density", 0},
	{OPT_ASPECT, M_RANDOM, "--aspect", "pack.aspect", 1},
	{OPT_LAW, M_RANDOM | M_FRONT | M_COMPRESS, "--law", "pack.radius.law", 0},
	{OPT_RMIN, M_RANDOM | M_FRONT | M_COMPRESS, "--rmin", "pack.radius.min", 0},
	{OPT_LAMBDA, M_RANDOM | M_FRONT | M_COMPRESS, "--lambda", "pack.radius.lambda", 0},
	{OPT_BOX, M_COMPRESS, "--box", "pack.box", 1},
	{OPT_CYLINDER, M_COMPRESS, "--cylinder", "pack.cylinder", 1},
	{OPT_PLANES, M_COMPRESS, "--planes", "pack.planes", 1},
	{OPT_NO_RELAX, M_COMPRESS, "--no-relax", "pack.relax", 0},
	{OPT_TOLERANCE, M_COMPRESS, "--tolerance", "pack.tolerance", 0},
	{OPT_SHAKES, M_COMPRESS, "--shakes", "pack.shakes", 0},
	{OPT_CONE, M_COMPRESS, "--cone", "pack.cone", 0},
	{OPT_FORM, M_FRONT, "--form", "pack.form", 0},
	{OPT_DOMAIN, M_FRONT, "--domain", "pack.domain", 1},
	{OPT_POLYGON, M_FRONT, "--polygon", "pack.polygon", 1},
	{OPT_CHECK_LIMIT, M_FRONT, "--check-limit", "pack.check_limit", 0},
	{OPT_GRAVITY, M_FRONT, "--gravity", "pack.gravity", 0},
	{OPT_SHAPE, M_FRONT, "--shape", "pack.shape", 0},
	{OPT_SIDES, M_FRONT, "--sides", "pack.sides", 0},
	{OPT_RATIO_LAW, M_FRONT, "--ratio-law", "pack.ratio.law", 0},
	{OPT_RATIO_MIN, M_FRONT, "--ratio-min", "pack.ratio.min", 0},
	{OPT_RATIO_MAX, M_FRONT, "--ratio-max", "pack.ratio.max", 0},
	{OPT_PATTERN, M_SHOTS, "--pattern", "pack.pattern", 0},
	{OPT_AREA, M_SHOTS, "--area", "pack.area", 1},
	{OPT_GRID, M_SHOTS, "--grid", "pack.grid", 0},
	{OPT_PASSES, M_SHOTS, "--passes", "pack.passes", 0},
	{OPT_COVERAGE, M_SHOTS, "--coverage", "pack.coverage", 0},
	{OPT_PER_PASS, M_SHOTS, "--per-pass", "pack.per_pass", 0},
	{OPT_SEPARATION, M_SHOTS, "--separation", "pack.separation", 0},
	{OPT_DIMPLE, M_SHOTS, "--dimple-radius", "pack.dimple_radius", 0},
	{OPT_SPEED, M_SHOTS, "--speed", "shot.speed", 0},
	{OPT_ANGLE, M_SHOTS, "--angle", "shot.angle", 0},
	{OPT_SHOT_RADIUS, M_SHOTS, "--shot-radius", "shot.radius", 0},
};
#define NMETHOD_OPTS (sizeof method_opts / sizeof method_opts[0])
_Static_assert(NMETHOD_OPTS <= 64, "a bit per method option");

/* Returns -1 to go on, or the exit code (help, version, usage error). */
static int parse_cmdline(int argc, char **argv, struct cmdline *cl)
{
	dem_cli_t c;
	dem_common_t *com = &cl->com;
	unsigned long long given = 0;   /* bit i: method_opts[i] was typed */
	const char *shape = NULL;       /* --shape as typed */
	int k;

	memset(cl, 0, sizeof *cl);
	if (dem_common_init(com, argc) || dem_cli_init(&c, PROG, options, usage, purpose, epilogue))
		return DEM_EIO;
	/* (of the common options, --accuracy has no use: packings have no knob yet) */
	while ((k = dem_cli_option(&c, com, argc, argv)) != -1) {
		if (k == OPT_VTK) {     /* an output, not a scene key */
			cl->vtk = optarg;
			continue;
		}
		if (k == OPT_STAGES) {
			cl->stages = optarg;
			continue;
		}
		if (k == OPT_SHAPE)     /* --vtk draws disks only: checked below */
			shape = optarg;
		for (size_t i = 0; i < NMETHOD_OPTS; i++) {
			const struct method_opt *o = &method_opts[i];
			if (k != o->key)
				continue;
			given |= 1ULL << i;
			if (!optarg)    /* a flag; --no-relax turns a key off */
				dem_common_override(com, o->scene_key,
						    k == OPT_NO_RELAX ? "false" : "true", o->name);
			else if (!o->vector)
				dem_common_override(com, o->scene_key, optarg, o->name);
			else if (dem_common_override_vector(com, o->scene_key, optarg, o->name))
				return DEM_EIO;
		}
	}
	if (c.done < 0) {
		if (optind < argc)
			cl->method = argv[optind++];
		int m = -1;
		for (int i = 0; cl->method && methods[i]; i++)
			if (strcmp(cl->method, methods[i]) == 0)
				m = i;
		if (!cl->method && !com->dump)
			dem_cli_error(&c, "no method given (random, front, shots or compress)");
		else if (cl->method && m < 0)
			dem_cli_error(&c, "unknown method '%s' (this version has: random, front, shots, compress)", cl->method);
		for (size_t i = 0; m >= 0 && i < NMETHOD_OPTS; i++)
			if ((given >> i & 1) && !(method_opts[i].methods >> m & 1))
				dem_cli_error(&c, "%s: not an option of method %s", method_opts[i].name, methods[m]);
		if (cl->vtk && m >= 0 && m != METHOD_FRONT && m != METHOD_COMPRESS)
			dem_cli_error(&c, "--vtk: not an option of method %s", methods[m]);
		if (cl->vtk && shape && strcmp(shape, "disk") != 0)
			dem_cli_error(&c, "--vtk: disks only, not with --shape %s (a body stream "
				      "is drawn by its rows, dem-streams(5))", shape);
		if (cl->stages && m >= 0 && m != METHOD_COMPRESS)
			dem_cli_error(&c, "--stages: not an option of method %s", methods[m]);
		if (m >= 0)     /* the method typed wins over the scene's */
			dem_common_override(com, "pack.method", cl->method, cl->method);
		if (optind < argc)
			dem_cli_error(&c, "unexpected argument '%s'", argv[optind]);
	}
	return dem_cli_done(&c);
}

/* A key whose items of per numbers are written flat, [a1, b1, a2, b2, ...]
 * (pack.polygon, pack.planes): the scene reader has vectors of a known
 * length only, so each multiple of per up to max items is tried in turn (a
 * nested [[a1, b1], ...] needs a scene getter for lists of vectors).  *v is
 * malloc'd with *n items, NULL when the key is absent.  An item that is
 * bad is reported as the scene reader says, nested items with the message
 * nested, and no length that fits with none ("%d": max). */
static int read_flat(dem_scene_t *s, const char *key, int per, int max, const char *nested,
		     const char *none, double **v, int *n, dem_error_t *e)
{
	dem_error_t e2;
	char item[64];

	*v = NULL;
	*n = 0;
	if (!dem_scene_has(s, key))
		return DEM_OK;
	double *buf = malloc((size_t)(per * max) * sizeof *buf);
	if (!buf)
		return dem_error_nomem(e, key + strlen("pack."));
	snprintf(item, sizeof item, "%s[", key);
	for (int k = per; k <= per * max; k += per) {
		dem_error_clear(&e2);
		if (dem_scene_vector(s, key, DEM_DIM_LENGTH, k, NULL,
				     -HUGE_VAL, HUGE_VAL, buf, &e2) == DEM_OK) {
			*v = buf;
			*n = k / per;
			return DEM_OK;
		}
		if (strstr(e2.msg, item)) {     /* an item is bad */
			free(buf);
			if (strstr(e2.msg, "got a sequence"))
				return dem_scene_error(s, key, e, "%s", nested);
			*e = e2;
			return e->code;
		}
	}
	free(buf);
	return dem_scene_error(s, key, e, none, max);
}

/* pack.polygon: the vertices, [x1, y1, x2, y2, ...] (lengths). */
#define MAXPOLY 4096
static int read_polygon(dem_scene_t *s, double **v, int *n, dem_error_t *e)
{
	dem_error_t e2 = {0};
	int rc = read_flat(s, "pack.polygon", 2, MAXPOLY,
			   "write the vertices flat: [x1, y1, x2, y2, ...] (lengths)",
			   "expected the vertices flat, [x1, y1, x2, y2, ...]: an even number "
			   "of lengths, 3 to %d vertices", v, n, e);

	if (rc || !*v)
		return rc;
	if (dem_front_polygon_check(*v, *n, &e2)) {
		free(*v);
		*v = NULL;
		*n = 0;
		return dem_scene_error(s, "pack.polygon", e, "%s", e2.msg);
	}
	return DEM_OK;
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
	double *poly;
	int npoly;
	if (read_polygon(s, &poly, &npoly, e))
		return e->code;
	fp->polygon = poly;
	fp->npolygon = npoly;
	if (poly && dem_scene_has(s, "pack.domain"))
		return dem_scene_error(s, "pack.domain", e, "not read with pack.polygon; give one or the other");
	if (poly && form != DEM_FRONT_OPEN)
		return dem_scene_error(s, "pack.polygon", e, "a polygon needs the open form (Ch. 5.2.2)");
	if (!(dom[0] < dom[2] && dom[1] < dom[3]))
		return dem_scene_error(s, "pack.domain", e,
				       "expected [xlo, ylo, xhi, yhi] with xlo < xhi and ylo < yhi");
	if (fp->gravity && form != DEM_FRONT_OPEN)
		return dem_scene_error(s, "pack.gravity", e,
				       "gravity needs the open form (Ch. 5.2.3)");
	int shape, rlaw;
	long sides;
	double amin, amax;
	if (dem_scene_choice(s, "pack.shape", dem_front_shape_names, DEM_FRONT_DISK, &shape, e) ||
	    dem_scene_int(s, "pack.sides", 6, 3, 64, &sides, e) ||
	    dem_scene_choice(s, "pack.ratio.law", dem_radius_names, DEM_RADIUS_URD, &rlaw, e) ||
	    dem_scene_quantity(s, "pack.ratio.min", DEM_DIM_NONE, 1, 1, 1e6, &amin, e) ||
	    dem_scene_quantity(s, "pack.ratio.max", DEM_DIM_NONE, amin, 1, 1e6, &amax, e))
		return e->code;
	static const char *const body_keys[] = {"pack.sides", "pack.ratio", NULL};
	for (int k = 0; body_keys[k]; k++)
		if (dem_scene_has(s, body_keys[k]) &&
		    (shape == DEM_FRONT_DISK || (k == 0 && shape != DEM_FRONT_POLYGON)))
			return dem_scene_error(s, body_keys[k], e, "not read with pack.shape %s",
					       dem_front_shape_names[shape]);
	if (amax < amin)
		return dem_scene_error(s, "pack.ratio.max", e, "expected at least pack.ratio.min (%g)", amin);
	fp->shape = (dem_front_shape_t)shape;
	fp->sides = (int)sides;
	if (shape != DEM_FRONT_DISK)
		fp->ratio = (dem_radius_law_t){(dem_radius_kind_t)rlaw, amin, amax};
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

/* pack.planes: the half-spaces, [nx1, ny1, nz1, d1, nx2, ...] (as
 * pack.polygon).  Each normal points into the domain and is scaled to unit
 * length together with its d, so give the normals as plain numbers and d
 * as a length.  *pl is malloc'd, NULL when the key is absent. */
#define MAXPLANES 256
static int read_planes(dem_scene_t *s, dem_plane_t **pl, size_t *n, dem_error_t *e)
{
	double *buf;
	int k, rc = read_flat(s, "pack.planes", 4, MAXPLANES,
			      "write the planes flat: [nx1, ny1, nz1, d1, nx2, ...]",
			      "expected the planes flat, [nx1, ny1, nz1, d1, ...]: 4 numbers "
			      "a plane, 1 to %d planes", &buf, &k, e);

	*pl = NULL;
	*n = 0;
	if (rc || !buf)
		return rc;
	dem_plane_t *q = malloc((size_t)k * sizeof *q);
	if (!q) {
		free(buf);
		return dem_error_nomem(e, "planes");
	}
	for (int i = 0; i < k; i++) {
		const double *b = buf + 4 * i;
		double len = sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
		if (!(len > 0)) {
			free(q);
			free(buf);
			return dem_scene_error(s, "pack.planes", e, "plane %d: the normal is zero", i + 1);
		}
		q[i] = (dem_plane_t){{b[0] / len, b[1] / len, b[2] / len}, b[3] / len};
	}
	free(buf);
	*pl = q;
	*n = (size_t)k;
	return DEM_OK;
}

/* The compress method's keys of the pack: section; the accuracy preset
 * sets tau (Eq. 6.8) and the end of settling unless the scene does. */
static int read_compress(dem_scene_t *s, int accuracy, dem_compress_spec_t *cp,
			 dem_plane_t **planes, dem_error_t *e)
{
	static const double box0[6] = {0, 0, 0, 20, 20, 20};
	static const double tau[3] = {1e-2, 1e-3, 1e-4}, ftol[3] = {3e-3, 1e-3, 3e-4};
	double box[6], cyl[5];
	long n, shakes;
	int relax;

	dem_compress_spec_init(cp);
	if (read_law(s, &cp->law, e) ||
	    dem_scene_vector(s, "pack.box", DEM_DIM_LENGTH, 6, box0, -HUGE_VAL, HUGE_VAL, box, e) ||
	    dem_scene_int(s, "pack.n", 0, 0, 4294967295L, &n, e) ||
	    dem_scene_bool(s, "pack.relax", 1, &relax, e) ||
	    dem_scene_quantity(s, "pack.tolerance", DEM_DIM_NONE, tau[accuracy], DEM_SCENE_GT0, 1, &cp->tol, e) ||
	    dem_scene_int(s, "pack.shakes", 5, 0, 1000, &shakes, e) ||
	    dem_scene_quantity(s, "pack.cone", DEM_DIM_NONE, 0.5, 0, 100, &cp->beta, e))
		return e->code;
	cp->relax_ftol = ftol[accuracy];
	cp->max_n = (size_t)n;
	cp->relax = relax;
	cp->nshake = (int)shakes;
	if (dem_scene_has(s, "pack.cylinder")) {
		if (dem_scene_has(s, "pack.box"))
			return dem_scene_error(s, "pack.box", e, "not read with pack.cylinder, "
					       "which is its own bounding box; give one or the other");
		if (dem_scene_vector(s, "pack.cylinder", DEM_DIM_LENGTH, 5, NULL, -HUGE_VAL, HUGE_VAL, cyl, e))
			return e->code;
		if (!(cyl[2] > 0 && cyl[3] < cyl[4]))
			return dem_scene_error(s, "pack.cylinder", e,
					       "expected [cx, cy, R, z0, z1] with R > 0 and z0 < z1");
		dem_domain_cylinder(&cp->dom, cyl[0], cyl[1], cyl[2], cyl[3], cyl[4]);
	} else {
		if (!(box[0] < box[3] && box[1] < box[4] && box[2] < box[5]))
			return dem_scene_error(s, "pack.box", e, "expected [xlo, ylo, zlo, xhi, yhi, zhi] "
					       "with each lo < hi");
		dem_domain_box(&cp->dom, box, box + 3);
	}
	if (read_planes(s, planes, &cp->dom.nplane, e))
		return e->code;
	cp->dom.plane = *planes;
	return DEM_OK;
}

/* A key that only the other pattern reads, given anyway. */
static int other_pattern(dem_scene_t *s, const char *const *keys, int pattern,
			 dem_error_t *e)
{
	for (int i = 0; keys[i]; i++)
		if (dem_scene_has(s, keys[i]))
			return dem_scene_error(s, keys[i], e, "not read with pack.pattern %s",
					       dem_shots_pattern_names[pattern]);
	return DEM_OK;
}

/* The shot: section (the shot itself) and the pattern keys of pack:. */
static int read_shots(dem_scene_t *s, dem_shots_spec_t *sp, dem_error_t *e)
{
	static const double area0[2] = {0.0056, 0.0056}, centre0[2] = {0, 0};
	static const char *const random_keys[] = {"pack.coverage", "pack.per_pass",
						  "pack.separation", NULL};
	static const char *const grid_keys[] = {"pack.grid", NULL};
	double area[2], centre[2], r, lambda, dimple = NAN, coverage = NAN;
	long grid = 4, passes = 32, per_pass = 8;
	int pattern, law;

	/* S550 shot at 46.5 m/s, normal to the surface: Ch. 8.6 */
	if (dem_scene_quantity(s, "shot.radius", DEM_DIM_LENGTH, 0.0007, DEM_SCENE_GT0, HUGE_VAL, &r, e) ||
	    dem_scene_choice(s, "shot.law", dem_radius_names, DEM_RADIUS_MONO, &law, e) ||
	    dem_scene_quantity(s, "shot.lambda", DEM_DIM_NONE, 1, 1, 1e9, &lambda, e) ||
	    dem_scene_quantity(s, "shot.speed", DEM_DIM_VELOCITY, 46.5, DEM_SCENE_GT0, HUGE_VAL, &sp->speed, e) ||
	    dem_scene_quantity(s, "shot.speed_scatter", DEM_DIM_NONE, 0, 0, 0.33, &sp->speed_scatter, e) ||
	    dem_scene_quantity(s, "shot.angle", DEM_DIM_ANGLE, DEM_PI / 2, DEM_SCENE_GT0, DEM_PI / 2, &sp->angle, e) ||
	    dem_scene_quantity(s, "shot.azimuth", DEM_DIM_ANGLE, 0, -2 * DEM_PI, 2 * DEM_PI, &sp->azimuth, e) ||
	    dem_scene_choice(s, "pack.pattern", dem_shots_pattern_names, DEM_SHOTS_GRID, &pattern, e) ||
	    dem_scene_vector(s, "pack.area", DEM_DIM_LENGTH, 2, area0, DEM_SCENE_GT0, HUGE_VAL, area, e) ||
	    dem_scene_vector(s, "pack.center", DEM_DIM_LENGTH, 2, centre0, -HUGE_VAL, HUGE_VAL, centre, e))
		return e->code;
	sp->pattern = (dem_shots_pattern_t)pattern;
	sp->law = (dem_radius_law_t){(dem_radius_kind_t)law, r, r * lambda};
	for (int d = 0; d < 2; d++) {
		sp->lo[d] = centre[d] - area[d] / 2;
		sp->hi[d] = centre[d] + area[d] / 2;
	}
	if (pattern == DEM_SHOTS_GRID) {
		if (other_pattern(s, random_keys, pattern, e) ||
		    dem_scene_int(s, "pack.grid", 4, 1, 65535, &grid, e) ||
		    dem_scene_int(s, "pack.passes", 32, 1, 1000000000L, &passes, e))
			return e->code;
	} else {
		if (other_pattern(s, grid_keys, pattern, e) ||
		    dem_scene_quantity(s, "pack.coverage", DEM_DIM_NONE, NAN, DEM_SCENE_GT0, 10000, &coverage, e) ||
		    dem_scene_int(s, "pack.per_pass", 8, 1, 1000000L, &per_pass, e) ||
		    dem_scene_quantity(s, "pack.separation", DEM_DIM_NONE, 1, 0, 100, &sp->separation, e))
			return e->code;
		/* a coverage decides the number of passes */
		if (isnan(coverage) && dem_scene_int(s, "pack.passes", 32, 1, 1000000000L, &passes, e))
			return e->code;
		if (!isnan(coverage) && dem_scene_has(s, "pack.passes"))
			return dem_scene_error(s, "pack.passes", e, "not read with pack.coverage, "
					       "which sets the number of passes; give one or the other");
	}
	if (dem_scene_quantity(s, "pack.dimple_radius", DEM_DIM_LENGTH, NAN, DEM_SCENE_GT0, HUGE_VAL, &dimple, e))
		return e->code;
	/* No default: the dimple depends on shot, speed and material, and
	 * demprofile measures it; a guess would make the coverage a guess. */
	if (!isnan(coverage) && isnan(dimple))
		return dem_scene_error(s, "pack.dimple_radius", e, "required with pack.coverage "
				       "(--coverage): the radius of one dimple, which the coverage "
				       "counts, e.g. 0.4 mm (--dimple-radius)");
	sp->grid = (int)grid;
	sp->passes = passes;
	sp->per_pass = per_pass;
	sp->coverage = isnan(coverage) ? 0 : coverage;
	sp->dimple_radius = isnan(dimple) ? 0 : dimple;
	return DEM_OK;
}

/* The pack: section, resolved: the method, then its keys. */
static int read_scene(dem_scene_t *s, int *method, dem_random_spec_t *sp,
		      dem_front_spec_t *fp, dem_shots_spec_t *hp,
		      dem_compress_spec_t *cp, dem_plane_t **planes, int accuracy,
		      dem_error_t *e)
{
	static const char *const sections[] = {"pack", NULL};
	static const char *const shot_sections[] = {"pack", "shot", NULL};
	long dim, n;
	const double one[3] = {1, 1, 1};

	if (dem_scene_choice(s, "pack.method", methods, METHOD_RANDOM, method, e))
		return e->code;
	if (*method == METHOD_SHOTS) {
		if (read_shots(s, hp, e))
			return e->code;
		return dem_scene_check(s, shot_sections, e);
	}
	if (*method == METHOD_FRONT) {
		if (read_law(s, &fp->law, e) || read_front(s, fp, e))
			return e->code;
		return dem_scene_check(s, sections, e);
	}
	if (*method == METHOD_COMPRESS) {
		if (read_compress(s, accuracy, cp, planes, e))
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
	const char *vtk_path;   /* --vtk, or NULL */
	dem_vtk_t *vtk;
	dem_front_shape_t shape; /* bodies: their shape, sides and count */
	int sides;
	size_t id;
};

static int front_open(struct front_out *o)
{
	char rho[32];
	o->t_packed = dem_wall();
	dem_fmt_double(rho, o->st->density);
	dem_header_set(o->h, "density", "%s", rho);
	int rc = dem_writer_open(&o->w, o->path, o->h, o->flags, o->e);
	if (rc == DEM_OK && o->vtk_path) {
		char title[80];
		snprintf(title, sizeof title, "dempack front: %zu disks, density %s", o->st->kept, rho);
		rc = dem_vtk_open(&o->vtk, o->vtk_path, 2, o->st->kept, title, o->e);
	}
	return rc;
}

static int front_emit(void *ctx, const double *x, double r)
{
	struct front_out *o = ctx;
	double row[3] = {x[0], x[1], r};
	int rc;

	if (!o->w && (rc = front_open(o)))
		return rc;
	if (o->vtk && (rc = dem_vtk_point(o->vtk, x, r, o->e))) {
		o->vtk = NULL;  /* freed */
		return rc;
	}
	return dem_writer_row(o->w, row, o->e);
}

static int front_emit_body(void *ctx, const dem_front_body_t *b)
{
	struct front_out *o = ctx;
	int rc;

	if (!o->w && (rc = front_open(o)))
		return rc;
	dem_body_row_t row = {0, (unsigned)o->id++, o->shape == DEM_FRONT_POLYGON ? DEM_SHAPE_POLYGON
						   : DEM_SHAPE_SUPERQUADRIC,
			      0, b->a, b->b, o->shape == DEM_FRONT_POLYGON ? o->sides : 2,
			      b->x[0], b->x[1], b->theta, 0, 0, 0};
	return dem_bodies_write_row(o->w, &row, o->e);
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
	if (fp->shape != DEM_FRONT_DISK) {
		if (cl->vtk)
			return dem_error_set(e, DEM_EINPUT, "--vtk: disks only (a body stream "
					     "is drawn by its rows, dem-streams(5))");
		char amin[32], amax[32];
		dem_fmt_double(amin, fp->ratio.rmin);
		dem_fmt_double(amax, fp->ratio.rmax);
		dem_header_add(h, "bodies", "shape=%s sides=%d ratio_law=%s ratio_min=%s ratio_max=%s",
			       dem_front_shape_names[fp->shape], fp->shape == DEM_FRONT_POLYGON ? fp->sides : 0,
			       dem_radius_names[fp->ratio.kind], amin, amax);
	}
	if (fp->polygon) {
		/* the vertices as given, x1 y1 x2 y2 ... */
		size_t cap = (size_t)fp->npolygon * 2 * 26 + 1, len = 0;
		char *line = malloc(cap);
		if (!line)
			return dem_error_nomem(e, "header");
		for (int i = 0; i < 2 * fp->npolygon; i++) {
			char v[32];
			dem_fmt_double(v, fp->polygon[i]);
			len += (size_t)snprintf(line + len, cap - len, "%s%s", i ? " " : "", v);
		}
		dem_header_set(h, "polygon", "%s", line);
		free(line);
	} else {
		dem_fmt_double(buf[0], fp->lo[0]);
		dem_fmt_double(buf[1], fp->lo[1]);
		dem_fmt_double(buf[2], fp->hi[0]);
		dem_fmt_double(buf[3], fp->hi[1]);
		dem_header_set(h, "domain", "%s %s %s %s", buf[0], buf[1], buf[2], buf[3]);
	}

	gsl_rng *rng = dem_rng_derive(cl->com.seed, 0);
	if (!rng)
		return dem_error_nomem(e, "random generator");
	struct front_out o = {NULL, h, &st, cl->com.output,
			      (cl->com.binary ? DEM_STREAM_BINARY : 0) | (cl->com.gzip ? DEM_STREAM_GZIP : 0), e, 0,
			      cl->vtk, NULL, fp->shape, fp->sides, 0};
	double t0 = dem_wall();
	rc = fp->shape == DEM_FRONT_DISK ? dem_pack_front(fp, rng, front_emit, &o, &st, e)
					 : dem_pack_front_bodies(fp, rng, front_emit_body, &o, &st, e);
	gsl_rng_free(rng);
	if (rc == DEM_OK && !o.w)
		rc = front_open(&o);
	if (rc == DEM_OK && o.vtk) {
		rc = dem_vtk_close(o.vtk, e);
		o.vtk = NULL;
	}
	if (rc == DEM_OK) {
		rc = dem_writer_close(o.w, e);
		o.w = NULL;
	}
	if (rc) {
		dem_vtk_abort(o.vtk);
		dem_writer_abort(o.w);
		return rc;
	}
	dem_cost_time(cost, "pack", o.t_packed - t0);
	dem_cost_time(cost, "write", dem_wall() - o.t_packed);
	dem_cost_count(cost, "objects", (double)st.kept);
	dem_cost_count(cost, "placed", (double)st.placed);
	dem_cost_count(cost, "density", st.density);
	dem_cost_count(cost, "failed", (double)st.failed);
	if (fp->shape == DEM_FRONT_ELLIPSE) {
		/* Newton on the loci (Ch. 5.4): solves, steps, refused, and
		 * the positions taken from the outer bounds instead */
		dem_cost_count(cost, "newton", (double)st.newton);
		dem_cost_count(cost, "newton_steps", (double)st.newton_iters);
		dem_cost_count(cost, "newton_refused", (double)st.newton_failed);
		dem_cost_count(cost, "fallbacks", (double)st.fallbacks);
		dem_cost_count(cost, "pw_evals", (double)st.overlap_evals);
	}
	return DEM_OK;
}

/* dempack compress: progress on stderr (unless -q) and the --stages table
 * at every stage; the writer opens at the first sphere, once the
 * statistics are complete, so the header carries the densities. */
struct compress_out {
	dem_writer_t *w;
	dem_header_t *h;
	const dem_compress_stats_t *st;
	const char *path;
	int flags, quiet, verbose;
	dem_error_t *e;
	double t_packed;
	const char *vtk_path;
	dem_vtk_t *vtk;
	FILE *stages;           /* --stages, a temporary file, or NULL */
};

static int compress_stage(void *ctx, const dem_compress_stage_t *s)
{
	struct compress_out *o = ctx;
	/* progress: with -v, or once a run takes a second */
	if (!o->quiet && (o->verbose || s->seconds >= 1))
		fprintf(stderr, "%s: compress: %-6s batch %d: %zu spheres (%zu added), "
			"density %.4f, %d iterations, %.2f s\n", PROG,
			dem_compress_phase_names[s->phase], s->batch, s->n, s->added,
			s->density, s->iters, s->seconds);
	if (o->stages)
		fprintf(o->stages, "%.6f\t%s\t%d\t%zu\t%zu\t%d\t%.6f\n", s->seconds,
			dem_compress_phase_names[s->phase], s->batch, s->n, s->added,
			s->iters, s->density);
	return 0;
}

static int compress_open(struct compress_out *o)
{
	char b[3][32];
	o->t_packed = dem_wall();
	dem_fmt_double(b[0], o->st->density);
	dem_fmt_double(b[1], o->st->density_top);
	dem_fmt_double(b[2], o->st->density_core);
	dem_header_set(o->h, "density", "%s", b[0]);
	dem_header_set(o->h, "density_top", "%s", b[1]);
	dem_header_set(o->h, "density_core", "%s", b[2]);
	int rc = dem_writer_open(&o->w, o->path, o->h, o->flags, o->e);
	if (rc == DEM_OK && o->vtk_path) {
		char title[80];
		snprintf(title, sizeof title, "dempack compress: %zu spheres, density %s", o->st->n, b[0]);
		rc = dem_vtk_open(&o->vtk, o->vtk_path, 3, o->st->n, title, o->e);
	}
	return rc;
}

static int compress_emit(void *ctx, const double *x, double r)
{
	struct compress_out *o = ctx;
	double row[4] = {x[0], x[1], x[2], r};
	int rc;

	if (!o->w && (rc = compress_open(o)))
		return rc;
	if (o->vtk && (rc = dem_vtk_point(o->vtk, x, r, o->e))) {
		o->vtk = NULL;  /* freed */
		return rc;
	}
	return dem_writer_row(o->w, row, o->e);
}

/* Pack by compression and write the spheres; h has the common lines. */
static int write_compress(dem_compress_spec_t *cp, const struct cmdline *cl,
			  dem_header_t *h, dem_cost_t *cost, dem_error_t *e)
{
	char b[8][32];
	dem_compress_stats_t st = {0};
	const dem_domain_t *d = &cp->dom;
	int rc;

	dem_fmt_double(b[0], cp->law.rmin);
	dem_fmt_double(b[1], cp->law.rmax / cp->law.rmin);
	dem_fmt_double(b[2], cp->tol);
	dem_fmt_double(b[3], cp->beta);
	dem_header_add(h, "method", "compress law=%s rmin=%s lambda=%s tolerance=%s shakes=%d "
		       "cone=%s relax=%s", dem_radius_names[cp->law.kind], b[0], b[1], b[2],
		       cp->nshake, b[3], cp->relax ? "true" : "false");
	if (d->cylinder) {
		dem_fmt_double(b[0], d->axis[0]);
		dem_fmt_double(b[1], d->axis[1]);
		dem_fmt_double(b[2], d->radius);
		dem_fmt_double(b[3], d->lo[2]);
		dem_fmt_double(b[4], d->hi[2]);
		dem_header_set(h, "cylinder", "%s %s %s %s %s", b[0], b[1], b[2], b[3], b[4]);
	} else {
		for (int k = 0; k < 3; k++) {
			dem_fmt_double(b[k], d->lo[k]);
			dem_fmt_double(b[3 + k], d->hi[k]);
		}
		dem_header_set(h, "box", "%s %s %s %s %s %s", b[0], b[1], b[2], b[3], b[4], b[5]);
	}
	for (size_t k = 0; k < d->nplane; k++) {
		const dem_plane_t *q = &d->plane[k];
		for (int m = 0; m < 3; m++)
			dem_fmt_double(b[m], q->n[m]);
		dem_fmt_double(b[3], q->d);
		dem_header_add(h, "plane", "%s %s %s %s", b[0], b[1], b[2], b[3]);
	}

	gsl_rng *rng = dem_rng_derive(cl->com.seed, 0);
	if (!rng)
		return dem_error_nomem(e, "random generator");
	struct compress_out o = {NULL, h, &st, cl->com.output,
				 (cl->com.binary ? DEM_STREAM_BINARY : 0) | (cl->com.gzip ? DEM_STREAM_GZIP : 0),
				 cl->com.quiet, cl->com.verbose, e, 0, cl->vtk, NULL, NULL};
	dem_afile_t stages = {0};
	if (cl->stages) {
		if ((rc = dem_afile_open(&stages, cl->stages, "w", e))) {
			gsl_rng_free(rng);
			return rc;
		}
		o.stages = stages.f;
		fprintf(o.stages, "# dempack compress stages: one row a stage\n"
			"# seconds\tphase\tbatch\tspheres\tadded\titerations\tdensity\n");
	}
	cp->stage = compress_stage;
	cp->stage_ctx = &o;
	double t0 = dem_wall();
	rc = dem_pack_compress(cp, rng, compress_emit, &o, &st, e);
	gsl_rng_free(rng);
	if (rc == DEM_OK && !o.w)
		rc = compress_open(&o);
	if (rc == DEM_OK && o.vtk) {
		rc = dem_vtk_close(o.vtk, e);
		o.vtk = NULL;
	}
	if (rc == DEM_OK) {
		rc = dem_writer_close(o.w, e);
		o.w = NULL;
	}
	if (rc == DEM_OK && stages.f)
		rc = dem_afile_commit(&stages, 0, e);
	dem_afile_abort(&stages);       /* nothing left after a commit */
	if (rc) {
		dem_vtk_abort(o.vtk);
		dem_writer_abort(o.w);
		return rc;
	}
	dem_cost_time(cost, "pack", o.t_packed - t0);
	dem_cost_time(cost, "write", dem_wall() - o.t_packed);
	dem_cost_count(cost, "objects", (double)st.n);
	dem_cost_count(cost, "density", st.density);
	dem_cost_count(cost, "density_top", st.density_top);
	dem_cost_count(cost, "density_core", st.density_core);
	dem_cost_count(cost, "batches", (double)st.batches);
	dem_cost_count(cost, "iterations", (double)st.iters);
	dem_cost_count(cost, "relax_steps", (double)st.steps);
	dem_cost_count(cost, "detections", (double)st.detections);
	if (st.removed)
		dem_cost_count(cost, "removed", (double)st.removed);
	return DEM_OK;
}

static int shots_emit(void *ctx, const dem_shot_t *sh)
{
	struct emit_ctx *c = ctx;
	double row[8] = {(double)sh->pass, sh->t, sh->x[0], sh->x[1], sh->r,
			 sh->v[0], sh->v[1], sh->v[2]};
	return dem_writer_row(c->w, row, c->e);
}

/* dempack shots: plan the stream (a dry run from the seed finds the number
 * of impacts a coverage needs, and the coverage reached), write the header
 * with it, then draw the same shots again and write them. */
static int write_shots(const dem_shots_spec_t *sp, const struct cmdline *cl,
		       int argc, char **args, dem_cost_t *cost, dem_error_t *e)
{
	static const char *const cols[] = {"t", "x", "y", "r", "vx", "vy", "vz"};
	static const char *const units[] = {"s", "m", "m", "m", "m/s", "m/s", "m/s"};
	char b[8][32];
	dem_header_t h;
	dem_shots_plan_t plan;
	dem_writer_t *w = NULL;
	int rc;

	double t0 = dem_wall();
	if ((rc = dem_shots_plan(sp, cl->com.seed, &plan, e)))
		return rc;
	if (plan.passes > 0xffffffffUL)
		return dem_error_set(e, DEM_EINPUT, "%zu passes: more than a u32 column holds", plan.passes);

	dem_header_init(&h, "shots", 1, 3);
	dem_header_add_col(&h, "pass", DEM_U32, "-");
	for (int i = 0; i < 7; i++)
		dem_header_add_col(&h, cols[i], DEM_F64, units[i]);
	dem_header_add_provenance(&h, PROG, argc, args, 1, cl->com.seed);
	dem_header_add(&h, "seed", "%lu", cl->com.seed);
	if (sp->pattern == DEM_SHOTS_GRID) {
		dem_header_add(&h, "method", "shots pattern=grid grid=%d passes=%zu per_pass=%zu",
			       sp->grid, plan.passes, plan.per_pass);
	} else {
		dem_fmt_double(b[0], sp->separation);
		dem_header_add(&h, "method", "shots pattern=random passes=%zu per_pass=%zu separation=%s",
			       plan.passes, plan.per_pass, b[0]);
	}
	dem_fmt_double(b[0], sp->law.rmin);
	dem_fmt_double(b[1], sp->law.rmax / sp->law.rmin);
	dem_fmt_double(b[2], sp->speed);
	dem_fmt_double(b[3], sp->speed_scatter);
	/* degrees to 12 digits, so 60 deg reads 60, not 59.99999999999999 */
	dem_header_add(&h, "shot", "law=%s radius=%s lambda=%s speed=%s speed_scatter=%s "
		       "angle_deg=%.12g azimuth_deg=%.12g", dem_radius_names[sp->law.kind],
		       b[0], b[1], b[2], b[3], sp->angle * 180 / DEM_PI, sp->azimuth * 180 / DEM_PI);
	dem_fmt_double(b[0], sp->lo[0]);
	dem_fmt_double(b[1], sp->lo[1]);
	dem_fmt_double(b[2], sp->hi[0]);
	dem_fmt_double(b[3], sp->hi[1]);
	dem_header_add(&h, "area", "%s %s %s %s", b[0], b[1], b[2], b[3]);
	if (sp->dimple_radius > 0) {
		char cov[160];
		int n = 0;
		if (sp->coverage > 0) {
			dem_fmt_double(b[4], sp->coverage);
			n += snprintf(cov + n, sizeof cov - (size_t)n, "target=%s ", b[4]);
		}
		dem_fmt_double(b[5], plan.covered);
		n += snprintf(cov + n, sizeof cov - (size_t)n, "covered=%s", b[5]);
		if (plan.impacts_100)   /* 0: the stream never covers 98 % */
			n += snprintf(cov + n, sizeof cov - (size_t)n, " impacts_100=%zu", plan.impacts_100);
		dem_fmt_double(b[6], sp->dimple_radius);
		snprintf(cov + n, sizeof cov - (size_t)n, " dimple_radius=%s", b[6]);
		dem_header_add(&h, "coverage", "%s", cov);
	}

	int flags = (cl->com.binary ? DEM_STREAM_BINARY : 0) | (cl->com.gzip ? DEM_STREAM_GZIP : 0);
	if ((rc = dem_writer_open(&w, cl->com.output, &h, flags, e)))
		goto out;
	struct emit_ctx ctx = {w, e, 0};
	if ((rc = dem_pack_shots(sp, cl->com.seed, &plan, shots_emit, &ctx, e)))
		goto out;
	rc = dem_writer_close(w, e);
	w = NULL;
	if (rc)
		goto out;
	dem_cost_time(cost, "pack", dem_wall() - t0);
	dem_cost_count(cost, "shots", (double)plan.shots);
	dem_cost_count(cost, "passes", (double)plan.passes);
	if (sp->dimple_radius > 0)
		dem_cost_count(cost, "coverage", plan.covered);
out:
	dem_writer_abort(w);
	dem_header_free(&h);
	return rc;
}

/* What the scene asks for: the method and its spec. */
struct job {
	dem_scene_t *scene;
	int method;
	dem_random_spec_t sp;
	dem_front_spec_t fp;
	dem_shots_spec_t hp;
	dem_compress_spec_t cp;
	dem_plane_t *planes;
	dem_header_t h;         /* of the particle stream */
};

/* The scene's settings with the options' overrides; --dump-scene prints
 * them. */
static int get_settings(const struct cmdline *cl, struct job *j, dem_error_t *e)
{
	int rc = dem_scene_open(&j->scene, &cl->com, e);

	if (!rc)
		rc = read_scene(j->scene, &j->method, &j->sp, &j->fp, &j->hp, &j->cp, &j->planes,
				cl->com.accuracy, e);
	if (!rc && cl->com.dump)
		dem_scene_dump(j->scene, stdout);
	return rc;
}

/* The particle stream's header: its columns, provenance and seed. */
static void particle_header(const struct cmdline *cl, struct job *j, const dem_main_t *r)
{
	const char *axes[] = {"x", "y", "z"};
	int dim = j->method == METHOD_FRONT ? 2 : j->method == METHOD_COMPRESS ? 3 : j->sp.dim;

	if (j->method == METHOD_FRONT && j->fp.shape != DEM_FRONT_DISK) {
		/* a body stream; its walls the domain's edges, anticlockwise
		 * (bodies on their left), as thick as the largest body */
		const dem_front_spec_t *f = &j->fp;
		double rect[8] = {f->lo[0], f->lo[1], f->hi[0], f->lo[1], f->hi[0], f->hi[1], f->lo[0], f->hi[1]};
		const double *v = f->polygon ? f->polygon : rect;
		int n = f->polygon ? f->npolygon : 4;
		double a2 = 0, t = 2 * f->law.rmax * sqrt(f->ratio.rmax);
		for (int k = 0; k < n; k++)
			a2 += v[2 * k] * v[2 * ((k + 1) % n) + 1] - v[2 * k + 1] * v[2 * ((k + 1) % n)];
		double (*wall)[5] = malloc((size_t)n * sizeof *wall);
		for (int k = 0; wall && k < n; k++) {
			int i = a2 > 0 ? k : n - 1 - k, i1 = a2 > 0 ? (k + 1) % n : (2 * n - 2 - k) % n;
			wall[k][0] = v[2 * i], wall[k][1] = v[2 * i + 1];
			wall[k][2] = v[2 * i1], wall[k][3] = v[2 * i1 + 1];
			wall[k][4] = t;
		}
		/* (without memory the header is short: the writer then fails) */
		dem_bodies_header(&j->h, wall ? (size_t)n : 0, (const double (*)[5])wall);
		free(wall);
		dem_header_add_provenance(&j->h, PROG, r->argc, r->args, 1, cl->com.seed);
		dem_header_add(&j->h, "seed", "%lu", cl->com.seed);
		return;
	}

	dem_header_init(&j->h, "particles", 1, dim);
	for (int d = 0; d < dim; d++)
		dem_header_add_col(&j->h, axes[d], DEM_F64, "m");
	dem_header_add_col(&j->h, "r", DEM_F64, "m");
	dem_header_add_provenance(&j->h, PROG, r->argc, r->args, 1, cl->com.seed);
	dem_header_add(&j->h, "seed", "%lu", cl->com.seed);
}

/* dempack random: the domain depends on the radii drawn, so it is sized
 * first, then the particles are written. */
static int write_random(const struct cmdline *cl, struct job *j, dem_cost_t *cost, dem_error_t *e)
{
	const dem_random_spec_t *sp = &j->sp;
	dem_writer_t *w = NULL;
	char rmin[32], lambda[32], rho[32];
	int rc;

	dem_fmt_double(rmin, sp->law.rmin);
	dem_fmt_double(lambda, sp->law.rmax / sp->law.rmin);
	dem_fmt_double(rho, sp->density);
	dem_header_add(&j->h, "method", "random law=%s rmin=%s lambda=%s density=%s",
		       dem_radius_names[sp->law.kind], rmin, lambda, rho);

	double hi[3] = {0, 0, 0};
	if ((rc = dem_pack_random_domain(sp, cl->com.seed, hi, e)))
		return rc;
	char buf[160];
	int n = 0;
	for (int d = 0; d < sp->dim; d++)
		n += snprintf(buf + n, sizeof buf - (size_t)n, "%s0", d ? " " : "");
	for (int d = 0; d < sp->dim; d++) {
		buf[n++] = ' ';
		n += dem_fmt_double(buf + n, hi[d]);
	}
	dem_header_set(&j->h, "domain", "%s", buf);
	int flags = (cl->com.binary ? DEM_STREAM_BINARY : 0) | (cl->com.gzip ? DEM_STREAM_GZIP : 0);
	if ((rc = dem_writer_open(&w, cl->com.output, &j->h, flags, e)))
		return rc;
	double t0 = dem_wall();
	struct emit_ctx ctx = {w, e, sp->dim};
	if ((rc = dem_pack_random(sp, cl->com.seed, hi, emit, &ctx, e))) {
		dem_writer_abort(w);
		return rc;
	}
	if ((rc = dem_writer_close(w, e)))
		return rc;
	dem_cost_time(cost, "pack", dem_wall() - t0);
	dem_cost_count(cost, "objects", (double)sp->n);
	return DEM_OK;
}

int main(int argc, char **argv)
{
	struct cmdline cl;
	struct job j = {0};
	dem_main_t r;
	int rc;

	if ((rc = dem_main_start(&r, PROG, argc, argv)))
		return rc;
	if ((rc = parse_cmdline(argc, argv, &cl)) >= 0)
		return dem_main_quit(&r, &cl.com, rc);
	if (!(rc = get_settings(&cl, &j, &r.e)) && !cl.com.dump) {
		gsl_rng *probe = dem_rng_new(&cl.com.have_seed, &cl.com.seed);  /* draws a seed if none */
		gsl_rng_free(probe);
		if (j.method == METHOD_SHOTS) {
			rc = write_shots(&j.hp, &cl, r.argc, r.args, &r.cost, &r.e);
		} else {
			particle_header(&cl, &j, &r);
			rc = j.method == METHOD_FRONT ? write_front(&j.fp, &cl, &j.h, &r.cost, &r.e) :
			     j.method == METHOD_COMPRESS ? write_compress(&j.cp, &cl, &j.h, &r.cost, &r.e) :
			     write_random(&cl, &j, &r.cost, &r.e);
		}
	}
	free((double *)j.fp.polygon);
	free(j.planes);
	dem_header_free(&j.h);
	dem_scene_free(j.scene);
	return dem_main_end(&r, &cl.com, rc);
}
