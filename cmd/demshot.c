/* demshot - the explicit finite element run of the peened block.
 *
 *   demshot [OPTION]... [SHOTS]
 *
 * Builds the block of the scene (graded hex8 mesh, face conditions, the J2
 * material) and integrates it in time with the central difference method
 * (lib/fe/explicit), and writes the state stream: the mesh, then the
 * displacements and element fields.  Two loads:
 *  - the shots of a shot stream (SHOTS, or standard input when the scene
 *    has no `load` section): rigid spheres hitting the top face (lib/shot,
 *    Ch. 3 and 7), pass by pass; a pass ends when the shots have left and
 *    the block's kinetic energy has fallen below a fraction of its peak,
 *    or at a maximum time; a frame is written at the end of each pass;
 *  - pressure pulses on the top face (the `load` section: the usual model
 *    of laser peening, and the test load of the explicit stage), frames
 *    evenly spaced up to run.end.
 * A scene with a `bodies` section is a DE-only run instead (Ch. 4): rigid
 * 2D superquadrics, polygons or disks with walls and gravity, no block
 * (lib/body); it writes the body stream, frames evenly spaced.
 *
 * Built with `make MPI=1` and started by mpirun, the 3D block runs on the
 * ranks (lib/fe/explicit.h, "Ranks"): every rank reads the scene and
 * builds the whole model; rank 0 reads the shot stream and sends each pass
 * to the others, which integrate the same shots; rank 0 alone writes the
 * outputs, the checkpoints and the messages (the others are silent), after
 * gathering the fields at each frame.  Points where only rank 0 can fail
 * (its streams and files) end with every rank agreeing on the outcome, so
 * no rank waits for one that has stopped.
 */
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <zlib.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "body/frames.h"
#include "body/setup.h"
#include "contact/law.h"
#include "contact/model.h"
#include "core/afile.h"
#include "core/cli.h"
#include "core/cost.h"
#include "core/rng.h"
#include "fe/explicit.h"
#include "fe/explicit2d.h"
#include "fe/fescene.h"
#include "io/scene.h"
#include "io/state.h"
#include "io/vtu.h"
#include "par/par.h"
#include "shot/shotset.h"
#include "shot/shotset2d.h"

#define PROG "demshot"

enum { OPT_END = DEM_OPT_PROGRAM, OPT_FRAMES, OPT_VTU, OPT_RULE, OPT_STRAIN,
       OPT_DAMPING, OPT_DT_FACTOR, OPT_THREADS, OPT_LAMBDA, OPT_FORCE, OPT_FORCES,
       OPT_PASS_TIME, OPT_STEADY, OPT_CHECKPOINT, OPT_RESUME };

static const dem_opt_t options[] = {
	{"end", OPT_END, "T", "simulated time, with a unit if wanted (20us)"},
	{"frames", OPT_FRAMES, "N", "state frames, evenly spaced, the last at the end (default 1)"},
	{"rule", OPT_RULE, "RULE", "one_point (hourglass control) or full (2x2x2, B-bar)"},
	{"strain", OPT_STRAIN, "KIND", "large (updated Lagrangian, Jaumann rate) or small"},
	{"damping", OPT_DAMPING, "XI", "mass-proportional damping: ratio of critical in the lowest mode (Ch. 7.5: 0.05)"},
	{"dt-factor", OPT_DT_FACTOR, "F", "time step over the stable element step, in (0, 1] (default 0.9)"},
	{"lambda", OPT_LAMBDA, "L", "contact time step factor of Box 3.1 (default 0.2; above 0.3 a warning, above 0.5 refused)"},
	{"force", OPT_FORCE, NULL, "run with a lambda above 0.5 all the same"},
	{"forces", OPT_FORCES, "FILE", "write the contact force history of the shots to FILE (a history stream)"},
	{"pass-time", OPT_PASS_TIME, "T", "longest time of a pass (default 200us)"},
	{"steady", OPT_STEADY, "F", "a pass ends when the block's kinetic energy is below F times its peak (default 0.01)"},
	{"checkpoint", OPT_CHECKPOINT, "FILE", "after each pass save the run to FILE (atomically) and its frames to FILE.journal"},
	{"resume", OPT_RESUME, NULL, "continue the run saved in the --checkpoint FILE (same scene and shots)"},
	{"vtu", OPT_VTU, "FILE", "also write the last frame to FILE for ParaView"},
	{"threads", OPT_THREADS, "N", "OpenMP threads for the element loop (default: OMP_NUM_THREADS or all)"},
	DEM_OPTS_COMMON,
	{0}
};

static const char usage[] = "Usage: demshot [OPTION]... [SHOTS]\n";
static const char purpose[] =
	"Integrate the peened block of the scene in time (explicit finite elements)\n"
	"under the shots of the shot stream SHOTS (standard input when the scene has\n"
	"no load section) or the scene's pressure load, and write its state stream\n"
	"(mesh, then displacements and element fields per pass or frame; binary,\n"
	"gzip-compressed) to standard output.  A scene with a bodies section is a\n"
	"DE-only run instead: rigid 2D superquadrics, polygons or disks with walls\n"
	"and gravity (Feng-Owen contact, Ch. 4), written as a body stream.\n";
static const char epilogue[] =
	"Examples:\n"
	"  dempack -s job.yaml shots | demshot -s job.yaml --forces f.txt -o job.state\n"
	"  demshot -s pulse.yaml --frames 4 -o pulse.state\n"
	"  demshot -s pulse.yaml --end 5us --rule full --vtu pulse.vtu | demprofile\n"
	"  demshot -s hopper.yaml --seed 1 --vtu last.vtu -o bodies.txt\n"
	"\nSee demshot(1), dem-scene(5) and dem-streams(5).\n";

struct cmdline {
	dem_common_t com;
	const char *vtu, *forces, *shots, *checkpoint;
	unsigned long threads;
	int force, resume;
};

static int parse_cmdline(int argc, char **argv, struct cmdline *cl)
{
	dem_cli_t c;
	dem_common_t *m = &cl->com;
	int k;

	memset(cl, 0, sizeof *cl);
	if (dem_common_init(m, argc) ||
	    dem_cli_init(&c, PROG, options, usage, purpose, epilogue))
		return DEM_EIO;
	while ((k = dem_cli_option(&c, m, argc, argv)) != -1) {
		switch (k) {
		case OPT_END: dem_common_override(m, "run.end", optarg, "--end"); break;
		case OPT_FRAMES: dem_common_override(m, "run.frames", optarg, "--frames"); break;
		case OPT_RULE: dem_common_override(m, "run.rule", optarg, "--rule"); break;
		case OPT_STRAIN: dem_common_override(m, "run.strain", optarg, "--strain"); break;
		case OPT_DAMPING: dem_common_override(m, "run.damping", optarg, "--damping"); break;
		case OPT_DT_FACTOR: dem_common_override(m, "run.dt_factor", optarg, "--dt-factor"); break;
		case OPT_VTU: cl->vtu = optarg; break;
		case OPT_LAMBDA: dem_common_override(m, "run.lambda", optarg, "--lambda"); break;
		case OPT_FORCE: cl->force = 1; break;
		case OPT_FORCES: cl->forces = optarg; break;
		case OPT_CHECKPOINT: cl->checkpoint = optarg; break;
		case OPT_RESUME: cl->resume = 1; break;
		case OPT_PASS_TIME: dem_common_override(m, "run.pass_time", optarg, "--pass-time"); break;
		case OPT_STEADY: dem_common_override(m, "run.steady", optarg, "--steady"); break;
		case OPT_THREADS:
			dem_cli_ulong(&c, "--threads", optarg, 1, 1024, &cl->threads);
			break;
		default: break;
		}
	}
	if (c.done < 0) {
		cl->shots = dem_cli_operand(&c, argc, argv, "shot stream");
		if (cl->resume && !cl->checkpoint)
			dem_cli_error(&c, "--resume needs --checkpoint FILE");
	}
	return dem_cli_done(&c);
}

/* A pressure pulse on a rectangle of the top face. */
struct pulse {
	double p;               /* peak pressure (Pa) */
	double area[2], centre[2];
	int nt;
	double *t, *f;          /* time table and the factors on p */
};

struct settings {
	dem_mat_t mat;
	dem_mesh_t mesh;        /* 2D: the state stream's, one element thick (mesh2.h) */
	dem_fe_opts_t fe;
	int dim;                /* 3, or 2: the block is mesh2 */
	int axisym;             /* dim 2: axisymmetric, else plane strain */
	double thick;           /* dim 2 plane strain: the slab's thickness (m) */
	dem_mesh2_t mesh2;
	double end, xi;         /* xi < 0: no damping */
	long frames;
	int have_load;
	struct pulse load;
	/* the shots (shot, contact sections) */
	int have_shots;
	dem_contact_model_t cm;
	dem_shotset_opts_t so;
	double pass_time, steady;
	int have_area;          /* the shot stream's impact area */
	double area[4];
	/* 2D plane strain: FE shots (shot.model: fe, feshot2d.h) */
	int fe_shot;
	double fe_ratio, fe_element;
};

static void settings_free(struct settings *st)
{
	dem_mat_free(&st->mat);
	dem_mesh_free(&st->mesh);
	dem_mesh2_free(&st->mesh2);
	free(st->load.t);
	free(st->load.f);
}

/* The load section: one pressure pulse. */
static int read_load(dem_scene_t *s, struct settings *st, dem_error_t *e)
{
	struct pulse *L = &st->load;
	static const double zero[2] = {0, 0};
	const dem_mesh_t *m = &st->mesh;
	double whole[2] = {m->gx[m->nx] - m->gx[0], m->gy[m->ny] - m->gy[0]};
	int n;

	st->have_load = dem_scene_has(s, "load");
	if (!st->have_load)
		return DEM_OK;
	L->p = NAN;
	if (dem_scene_quantity(s, "load.pressure", DEM_DIM_PRESSURE, NAN,
			       -HUGE_VAL, HUGE_VAL, &L->p, e) ||
	    dem_scene_vector(s, "load.area", DEM_DIM_LENGTH, 2, whole,
			     DEM_SCENE_GT0, HUGE_VAL, L->area, e) ||
	    dem_scene_vector(s, "load.center", DEM_DIM_LENGTH, 2, zero,
			     -HUGE_VAL, HUGE_VAL, L->centre, e))
		return e->code;
	if (isnan(L->p))
		return dem_scene_error(s, "load.pressure", e, "missing: the load "
				       "needs its pressure");
	n = dem_scene_length(s, "load.times");
	if (n < 0) {
		/* a step load held for the whole run */
		L->nt = 1;
		L->t = malloc(sizeof *L->t);
		L->f = malloc(sizeof *L->f);
		if (!L->t || !L->f)
			return dem_error_nomem(e, "load");
		L->t[0] = 0, L->f[0] = 1;
		return DEM_OK;
	}
	if (n < 1 || dem_scene_length(s, "load.factors") != n)
		return dem_scene_error(s, "load.factors", e, "expected a list of "
				       "%d factors, one per time of load.times",
				       n > 0 ? n : 1);
	L->nt = n;
	L->t = malloc((size_t)n * sizeof *L->t);
	L->f = malloc((size_t)n * sizeof *L->f);
	if (!L->t || !L->f)
		return dem_error_nomem(e, "load");
	if (dem_scene_vector(s, "load.times", DEM_DIM_TIME, n, NULL, 0, HUGE_VAL,
			     L->t, e) ||
	    dem_scene_vector(s, "load.factors", DEM_DIM_NONE, n, NULL, -HUGE_VAL,
			     HUGE_VAL, L->f, e))
		return e->code;
	for (int i = 1; i < n; i++)
		if (L->t[i] < L->t[i - 1])
			return dem_scene_error(s, "load.times", e, "the times must "
					       "not decrease (%g s after %g s)",
					       L->t[i], L->t[i - 1]);
	return DEM_OK;
}

/* The shot and contact sections, and the pass keys of run. */
static int read_shots(dem_scene_t *s, int accuracy, struct settings *st, dem_error_t *e)
{
	static const char *const laws[] = {"power", "hertz", NULL};
	static const char *const partials[] = {"potential", "area", "volume", NULL};
	/* 2D plane strain: disk.h's potential scheme (the default, as in 3D:
	 * the only one of the three whose forces conserve energy, issue 18,
	 * tests/unit/test_shot_impact2d.c), or the overlap area or contact
	 * width factor (Eqs. 3.10, 3.11); axisymmetric: the ring's surface
	 * (shotset2d.h), not chosen */
	static const char *const partials2[] = {"potential", "area", "width", NULL};
	static const int partial2_ids[] = {DEM_PARTIAL_POTENTIAL, DEM_PARTIAL_AREA, DEM_PARTIAL_WIDTH};
	static const char *const models[] = {"rigid", "fe", NULL};
	const int plane2 = st->dim == 2 && !st->axisym;
	dem_contact_param_t p = {0};
	double m, alpha, h = HUGE_VAL;
	int law, partial = 0;

	for (int i = 0; i < st->mesh.nx; i++)
		h = fmin(h, st->mesh.gx[i + 1] - st->mesh.gx[i]);
	memset(&st->so, 0, sizeof st->so);
	if (dem_scene_quantity(s, "shot.density", DEM_DIM_DENSITY, 7800, DEM_SCENE_GT0,
			       HUGE_VAL, &st->so.rho, e) ||
	    dem_scene_quantity(s, "shot.gap", DEM_DIM_LENGTH, h / 10, 0, HUGE_VAL,
			       &st->so.gap, e) ||
	    dem_scene_quantity(s, "shot.buffer", DEM_DIM_LENGTH, h, DEM_SCENE_GT0,
			       HUGE_VAL, &st->so.buffer, e) ||
	    dem_scene_choice(s, "contact.law", laws, 0, &law, e) ||
	    dem_scene_quantity(s, "contact.m", DEM_DIM_NONE, DEM_LAW_M_HERTZ, 1, 4, &m, e) ||
	    dem_scene_quantity(s, "contact.alpha", DEM_DIM_NONE, 2.5, DEM_SCENE_GT0,
			       HUGE_VAL, &alpha, e) ||
	    (st->dim == 3 &&
	     dem_scene_choice(s, "contact.partial", partials, DEM_PARTIAL_POTENTIAL, &partial, e)) ||
	    (plane2 && dem_scene_choice(s, "contact.partial", partials2, 0, &partial, e)) ||
	    dem_scene_quantity(s, "run.lambda", DEM_DIM_NONE,
			       accuracy == DEM_ACCURACY_FINE ? 0.1 :
			       accuracy == DEM_ACCURACY_COARSE ? 0.3 : DEM_DT_LAMBDA_DEFAULT,
			       -HUGE_VAL, HUGE_VAL, &st->so.lambda, e) ||
	    dem_scene_quantity(s, "run.pass_time", DEM_DIM_TIME, 200e-6, DEM_SCENE_GT0,
			       HUGE_VAL, &st->pass_time, e) ||
	    dem_scene_quantity(s, "run.steady", DEM_DIM_NONE, 0.01, DEM_SCENE_GT0, 1,
			       &st->steady, e) ||
	    dem_scene_choice(s, "shot.model", models, 0, &st->fe_shot, e))
		return e->code;
	if (st->fe_shot && !plane2)
		return dem_scene_error(s, "shot.model", e, "FE shots need a plane strain block "
				       "(dim: 2, block.mode: plane)");
	/* the FE shot of Ch. 7.4: E_s = 100 E "to approximately represent a
	 * rigid shot"; its element at the rim that of the block's surface */
	if (st->fe_shot &&
	    (dem_scene_quantity(s, "shot.modulus_ratio", DEM_DIM_NONE, 100, DEM_SCENE_GT0, HUGE_VAL,
				&st->fe_ratio, e) ||
	     dem_scene_quantity(s, "shot.element", DEM_DIM_LENGTH, h, DEM_SCENE_GT0, HUGE_VAL,
				&st->fe_element, e)))
		return e->code;
	if (plane2) {
		/* a disk's law per unit thickness (law.h dim = 2); hertz: the
		 * generalised Hertz law of a rigid disk (Eqs. 3.30-3.32) */
		if (law == 1 ? dem_law_ghertz2d(&p.law, st->mat.E, st->mat.nu, e)
			     : dem_law_init_dim(&p.law, alpha, st->mat.E, m, 2, e))
			return e->code;
		partial = partial2_ids[partial];
	} else if (law == 1) {
		if (dem_law_hertz(&p.law, st->mat.E, st->mat.nu, e))
			return e->code;
	} else if (dem_law_init(&p.law, alpha, st->mat.E, m, e)) {
		return e->code;
	}
	p.partial = st->dim == 2 && st->axisym ? DEM_PARTIAL_AREA : partial;
	/* the effects the scene gives (DESIGN.md) */
	if (dem_scene_has(s, "contact.friction")) {
		p.friction = 1;
		if (dem_scene_quantity(s, "contact.friction", DEM_DIM_NONE, 0, 0, HUGE_VAL,
				       &p.mu, e) ||
		    dem_scene_quantity(s, "contact.kt_ratio", DEM_DIM_NONE, DEM_CONTACT_KT_RATIO,
				       DEM_SCENE_GT0, HUGE_VAL, &p.kt_ratio, e))
			return e->code;
	}
	/* what the FE shot's penalty can be (feshot2d.h), said at its key */
	if (st->fe_shot && law == 1)
		return dem_scene_error(s, "contact.law", e, "an FE shot's penalty is the Winkler "
				       "form of the power law of m = 1.5, not the hertz law");
	if (st->fe_shot && m != DEM_LAW_M_HERTZ)
		return dem_scene_error(s, "contact.m", e, "an FE shot's penalty is the Winkler "
				       "form of the power law of m = 1.5 (got %g)", m);
	if (st->fe_shot && dem_scene_has(s, "contact.friction"))
		return dem_scene_error(s, "contact.friction", e, "no friction with an FE shot");
	if (st->fe_shot && dem_scene_has(s, "contact.unload"))
		return dem_scene_error(s, "contact.unload", e, "no hysteresis with an FE shot");
	if (dem_scene_has(s, "contact.damping") && dem_scene_has(s, "contact.unload"))
		return dem_scene_error(s, "contact.unload", e, "give one energy loss: "
				       "damping (viscous) or unload (hysteresis)");
	if (dem_scene_has(s, "contact.damping")) {
		p.damping = DEM_DAMP_VISCOUS;
		if (dem_scene_quantity(s, "contact.damping", DEM_DIM_NONE, 0, 0, 0.999999,
				       &p.xi, e))
			return e->code;
	}
	if (dem_scene_has(s, "contact.unload")) {
		p.damping = DEM_DAMP_HYSTERESIS;
		if (dem_scene_quantity(s, "contact.unload", DEM_DIM_NONE, 1, 1, HUGE_VAL,
				       &p.unload, e))
			return e->code;
	}
	return dem_contact_model_init(&st->cm, &p, e);
}

static int read_scene(dem_scene_t *s, int accuracy, int shots, struct settings *st,
		      dem_error_t *e)
{
	static const char *const sections[] = {"material", "block", "run", "load", "shot",
					       "contact", NULL};
	static const char *const rules[] = {"one_point", "full", NULL};
	static const char *const strains[] = {"small", "large", NULL};
	int rule, large;

	long dim;

	dem_fe_opts_default(&st->fe);
	st->xi = -1;
	if (dem_scene_int(s, "dim", 3, 2, 3, &dim, e) ||
	    dem_scene_material(s, 1, &st->mat, e))
		return e->code;
	st->dim = (int)dim;
	if (dim == 3 && dem_scene_block(s, &st->mesh, e))
		return e->code;
	/* 2D: the block in the x-z plane, and for the streams the 3D programs
	 * read the same mesh one element thick in y (mesh2.h); axisymmetric:
	 * as thick as the finest element (a view, not a measure) */
	if (dim == 2 && (dem_scene_block2(s, &st->mesh2, &st->axisym, &st->thick, e) ||
			 dem_mesh2_extrude(&st->mesh2, st->axisym ? st->mesh2.gx[1] - st->mesh2.gx[0]
								  : st->thick, &st->mesh, e)))
		return e->code;
	/* the accuracy preset chooses the element unless the scene does; the
	 * strain measure is large for every preset: small strain drops the
	 * quadratic part of the strain, several times the yield strain in a
	 * dimple (40 % off the peak residual stress of the Ch. 7.5 shot,
	 * examples/cost/STRAIN.md), so it is no coarse version of the same
	 * model */
	if (dem_scene_choice(s, "run.rule", rules,
			     accuracy == DEM_ACCURACY_FINE ? 1 : 0, &rule, e) ||
	    dem_scene_choice(s, "run.strain", strains,
			     1, &large, e) ||
	    dem_scene_quantity(s, "run.end", DEM_DIM_TIME, NAN, DEM_SCENE_GT0,
			       HUGE_VAL, &st->end, e) ||
	    dem_scene_int(s, "run.frames", 1, 1, 100000, &st->frames, e) ||
	    dem_scene_quantity(s, "run.dt_factor", DEM_DIM_NONE, st->fe.dt_factor,
			       DEM_SCENE_GT0, 1, &st->fe.dt_factor, e) ||
	    dem_scene_quantity(s, "run.hourglass", DEM_DIM_NONE, st->fe.hg_stiff,
			       0, 1, &st->fe.hg_stiff, e) ||
	    dem_scene_quantity(s, "run.damping", DEM_DIM_NONE, NAN, 0, 1, &st->xi, e))
		return e->code;
	st->fe.rule = rule ? DEM_FE_FULL : DEM_FE_1PT;
	st->fe.large = large;
	if (read_load(s, st, e))
		return e->code;
	if (st->dim == 2 && st->have_load)
		return dem_scene_error(s, "load", e, "a 2D block (dim: 2) takes shots "
				       "only, not a pressure load");
	/* a shot stream: the argument, or standard input without a load */
	st->have_shots = shots || !st->have_load;
	if (isnan(st->end) && !st->have_shots)
		return dem_scene_error(s, "run.end", e, "missing: how long to "
				       "run (e.g. 20 us)");
	if (isnan(st->xi))
		st->xi = -1;    /* no damping: the effect is absent */
	else
		st->fe.damping = st->dim == 2
			? dem_fe2_damping_alpha(&st->mat, st->xi, -st->mesh2.gy[0])
			: dem_fe_damping_alpha(&st->mat, st->xi, -st->mesh.gz[0]);
	if (st->have_shots && read_shots(s, accuracy, st, e))
		return e->code;
	return dem_scene_check(s, sections, e);
}

/* Put the load on the model. */
static int apply_load(dem_fe_t *fe, const struct settings *st, dem_error_t *e)
{
	const struct pulse *L = &st->load;
	double x0 = L->centre[0] - L->area[0] / 2, x1 = L->centre[0] + L->area[0] / 2;
	double y0 = L->centre[1] - L->area[1] / 2, y1 = L->centre[1] + L->area[1] / 2;
	size_t nq = dem_fe_top_quads(&st->mesh, x0, x1, y0, y1, NULL);
	uint32_t *q;
	double *p;
	int rc;

	if (nq == 0)
		return dem_error_set(e, DEM_EINPUT, "load: no face of the top "
				     "lies in the load area [%g, %g] x [%g, %g] m",
				     x0, x1, y0, y1);
	q = malloc(4 * nq * sizeof *q);
	p = malloc((size_t)L->nt * sizeof *p);
	if (!q || !p) {
		free(q), free(p);
		return dem_error_nomem(e, "load");
	}
	dem_fe_top_quads(&st->mesh, x0, x1, y0, y1, q);
	for (int i = 0; i < L->nt; i++)
		p[i] = L->p * L->f[i];
	rc = dem_fe_add_pressure(fe, nq, q, (size_t)L->nt, L->t, p, e);
	free(q);
	free(p);
	return rc;
}

/* The effects simulated, for the log (DESIGN.md). */
static void log_effects(const struct settings *st)
{
	const dem_mat_t *m = &st->mat;

	fprintf(stderr, "%s: effects: %s", PROG,
		m->flags & DEM_MAT_PLASTIC ? "J2 plasticity" : "elasticity");
	if (m->flags & DEM_MAT_PLASTIC)
		fprintf(stderr, " (%s hardening)", dem_mat_law_name(m));
	if (m->flags & DEM_MAT_KIN)
		fprintf(stderr, ", %d back-stress%s", m->nkin, m->nkin > 1 ? "es" : "");
	if (m->flags & DEM_MAT_RATE)
		fprintf(stderr, ", rate dependence (%s)", dem_mat_rate_name(m));
	if (st->dim == 2)
		fprintf(stderr, ", 2D %s", st->axisym ? "axisymmetric" : "plane strain");
	fprintf(stderr, ", %s strain, %s", st->fe.large ? "large" : "small",
		st->fe.rule == DEM_FE_FULL ? (st->dim == 2 ? "full 2x2 B-bar integration"
						: "full 2x2x2 B-bar integration")
		: "one-point integration with hourglass control");
	if (st->xi >= 0)
		fprintf(stderr, ", damping %g of critical", st->xi);
	fprintf(stderr, "%s", st->have_load ? ", pressure load" : "");
	if (st->have_shots && st->fe_shot)
		fprintf(stderr, ", shots: FE disks (E_s = %g E, element %g m), node-to-segment "
			"penalty, the Winkler form of the contact %s", st->fe_ratio, st->fe_element,
			st->cm.effects);
	else if (st->have_shots)
		fprintf(stderr, ", shots: contact %s, %s%s, lambda %g",
			st->cm.effects, st->dim == 3 ? "sphere/sphere" : st->axisym ?
			"one sphere on the axis" : "disk/disk", st->dim == 3 && st->cm.sepfix ?
			" (separation correction)" : "", st->so.lambda);
	fputc('\n', stderr);
}

/* Field buffers for a frame (of st->mesh); in 2D also the 2D model's,
 * lifted onto it (mesh2.h). */
struct fields {
	double *u, *sig, *eps, *ep;
	double *u2, *sig2, *eps2, *ep2;
};

static int fields_alloc(struct fields *f, const struct settings *st)
{
	const dem_mesh_t *m = &st->mesh;
	const dem_mesh2_t *m2 = &st->mesh2;
	f->u = malloc(3 * m->nn * sizeof *f->u);
	f->sig = malloc(6 * m->ne * sizeof *f->sig);
	f->eps = malloc(6 * m->ne * sizeof *f->eps);
	f->ep = malloc(m->ne * sizeof *f->ep);
	if (!f->u || !f->sig || !f->eps || !f->ep)
		return -1;
	if (st->dim == 3)
		return 0;
	f->u2 = malloc(2 * m2->nn * sizeof *f->u2);
	f->sig2 = malloc(6 * m2->ne * sizeof *f->sig2);
	f->eps2 = malloc(6 * m2->ne * sizeof *f->eps2);
	f->ep2 = malloc(m2->ne * sizeof *f->ep2);
	return f->u2 && f->sig2 && f->eps2 && f->ep2 ? 0 : -1;
}

static void fields_free(struct fields *f)
{
	free(f->u), free(f->sig), free(f->eps), free(f->ep);
	free(f->u2), free(f->sig2), free(f->eps2), free(f->ep2);
}

/* The block's model and its shots: the 3D ones (fe, S) or the 2D ones
 * (fe2, S2); the calls below take the one there is. */
struct blk {
	dem_par_t *par;         /* the ranks (NULL or one: this process) */
	dem_fe_t *fe;
	dem_shotset_t *S;
	dem_fe2_t *fe2;
	dem_shotset2d_t *S2;
	const dem_mesh2_t *m2;
};

static double blk_time(const struct blk *b)
{
	return b->fe2 ? dem_fe2_time(b->fe2) : dem_fe_time(b->fe);
}

static double blk_dt(const struct blk *b)
{
	return b->fe2 ? dem_fe2_dt(b->fe2) : dem_fe_dt(b->fe);
}

static long blk_steps(const struct blk *b)
{
	return b->fe2 ? dem_fe2_steps(b->fe2) : dem_fe_steps(b->fe);
}

static int blk_step(struct blk *b, double dt, dem_error_t *e)
{
	return b->fe2 ? dem_fe2_step(b->fe2, dt, e) : dem_fe_step(b->fe, dt, e);
}

static void blk_energy(const struct blk *b, dem_fe_energy_t *en)
{
	if (b->fe2)
		dem_fe2_energy(b->fe2, en);
	else
		dem_fe_energy(b->fe, en);
}

static void blk_stats(const struct blk *b, dem_fe_stats_t *fs)
{
	if (b->fe2)
		dem_fe2_stats(b->fe2, fs);
	else
		dem_fe_stats(b->fe, fs);
}

static int blk_save(const struct blk *b, FILE *f, dem_error_t *e)
{
	return b->fe2 ? dem_fe2_save(b->fe2, f, e) : dem_fe_save(b->fe, f, e);
}

static int blk_load(struct blk *b, FILE *f, dem_error_t *e)
{
	return b->fe2 ? dem_fe2_load(b->fe2, f, e) : dem_fe_load(b->fe, f, e);
}

/* The fields of the last state; with several ranks every rank's part is
 * gathered first (collective), and rank 0 alone, which writes them, fills
 * f. */
static void fields_get(const struct blk *b, struct fields *f)
{
	if (!b->fe2) {
		dem_fe_sync(b->fe);
		if (dem_par_rank(b->par) != 0)
			return;
		dem_fe_displacements(b->fe, f->u);
		dem_fe_fields(b->fe, f->sig, f->eps, f->ep);
		return;
	}
	dem_fe2_displacements(b->fe2, f->u2);
	dem_fe2_fields(b->fe2, f->sig2, f->eps2, f->ep2);
	dem_mesh2_lift(b->m2, f->u2, f->sig2, f->eps2, f->ep2, f->u, f->sig, f->eps, f->ep);
}

static int sh_begin(struct blk *b, size_t n, const dem_shot_t *sh, dem_error_t *e)
{
	return b->S2 ? dem_shotset2d_begin(b->S2, n, sh, dem_fe2_coords(b->fe2), e)
		     : dem_shotset_begin(b->S, n, sh, dem_fe_coords(b->fe), e);
}

static int sh_prepare(struct blk *b, double *dt, dem_error_t *e)
{
	return b->S2 ? dem_shotset2d_prepare(b->S2, dem_fe2_coords(b->fe2), dem_fe2_velocity(b->fe2),
					     dem_fe2_dt(b->fe2), dt, e)
		     : dem_shotset_prepare(b->S, dem_fe_coords(b->fe), dem_fe_velocity(b->fe),
					   dem_fe_dt(b->fe), dt, e);
}

static int sh_done(const struct blk *b)
{
	return b->S2 ? dem_shotset2d_done(b->S2) : dem_shotset_done(b->S);
}

static size_t sh_holding(const struct blk *b, size_t *touch, size_t *coming)
{
	return b->S2 ? dem_shotset2d_holding(b->S2, touch, coming)
		     : dem_shotset_holding(b->S, touch, coming);
}

static size_t sh_count(const struct blk *b)
{
	return b->S2 ? dem_shotset2d_count(b->S2) : dem_shotset_count(b->S);
}

static const dem_shot_body_t *sh_body(const struct blk *b, size_t i)
{
	return b->S2 ? dem_shotset2d_body(b->S2, i) : dem_shotset_body(b->S, i);
}

static void sh_stats(const struct blk *b, dem_shotset_stats_t *ss)
{
	if (b->S2)
		dem_shotset2d_stats(b->S2, ss);
	else
		dem_shotset_stats(b->S, ss);
}

/* With several ranks, after a step that only rank 0 can fail (its
 * streams and files): every rank returns the worst code. */
static int agree(dem_par_t *p, int rc, dem_error_t *e)
{
	if (dem_par_size(p) == 1)
		return rc;
	int m = dem_par_max_int(p, rc);
	if (m && !rc)
		return dem_error_set(e, m, "rank 0 failed");
	return m;
}

static int root(const struct blk *b)
{
	return dem_par_rank(b->par) == 0;
}

static int open_state(const struct cmdline *cl, const struct settings *st,
		      int argc, char **args, dem_state_writer_t **w,
		      dem_error_t *e)
{
	const dem_mesh_t *m = &st->mesh;
	dem_header_t h;
	double ax = st->have_load ? st->load.area[0] : m->gx[m->nx] - m->gx[0];
	double ay = st->have_load ? st->load.area[1] : m->gy[m->ny] - m->gy[0];
	double cx = st->have_load ? st->load.centre[0] : 0;
	double cy = st->have_load ? st->load.centre[1] : 0;
	if (st->have_area) {
		ax = st->area[2] - st->area[0], ay = st->area[3] - st->area[1];
		cx = (st->area[0] + st->area[2]) / 2, cy = (st->area[1] + st->area[3]) / 2;
	}
	if (st->dim == 2)       /* the x-z plane: all of the layer in y */
		ay = m->gy[1] - m->gy[0], cy = 0;
	/* axisymmetric, no impact area: the whole top face is the disk of the
	 * block's radius (x the radius from the axis x = 0) */
	if (st->dim == 2 && st->axisym && !st->have_area)
		ax = 2 * m->gx[m->nx];
	int rc;

	/* the metadata lines of the header (kind and columns are the state
	 * writer's) */
	dem_header_init(&h, "state", 1, 3);
	if (dem_header_add_provenance(&h, PROG, argc, args, 0, 0) ||
	    dem_header_set(&h, "area", "%.17g %.17g %.17g %.17g", cx - ax / 2,
			   cy - ay / 2, cx + ax / 2, cy + ay / 2) ||
	    dem_header_set(&h, "run", "end=%.17g frames=%ld rule=%s strain=%s "
			   "dt_factor=%g damping=%g", st->end, st->frames,
			   st->fe.rule == DEM_FE_FULL ? "full" : "one_point",
			   st->fe.large ? "large" : "small", st->fe.dt_factor,
			   st->xi >= 0 ? st->xi : 0) ||
	    (st->dim == 2 && (st->axisym
			      ? dem_header_set(&h, "twod", "mode=axisym")
			      : dem_header_set(&h, "twod", "mode=plane thickness=%.17g", st->thick)))) {
		dem_header_free(&h);
		return dem_error_nomem(e, "header");
	}
	rc = dem_state_writer_open(w, cl->com.output, m, &h, DEM_STATE_FLAGS, e);
	dem_header_free(&h);
	return rc;
}

/* Run to the end, writing the frames; progress on stderr every 2 s. */
static int run(struct blk *b, const struct settings *st, int quiet,
	       dem_state_writer_t *w, struct fields *f, dem_cost_t *cost,
	       dem_error_t *e)
{
	dem_fe_t *fe = b->fe;
	double next_report = dem_wall() + 2, twrite = 0;
	long k = 1;
	int rc;

	while (k <= st->frames) {
		double tf = st->end * (double)k / (double)st->frames;
		double t = dem_fe_time(fe), dt = dem_fe_dt(fe);

		if (t + dt >= tf) {
			/* land on the frame time: the step is cut, never
			 * stretched past the stable one */
			dt = tf - t;
			if (dt > 0 && (rc = dem_fe_step(fe, dt, e)))
				return rc;
			double t0 = dem_wall();
			fields_get(b, f);
			rc = root(b) ? dem_state_write_frame(w, 1, dem_fe_time(fe), f->u,
							     f->sig, f->eps, f->ep, e) : 0;
			if ((rc = agree(b->par, rc, e)))
				return rc;
			twrite += dem_wall() - t0;
			k++;
			continue;
		}
		if ((rc = dem_fe_step(fe, dt, e)))
			return rc;
		if (!quiet && dem_wall() > next_report) {
			dem_fe_energy_t en;

			dem_fe_energy(fe, &en);
			fprintf(stderr, "%s: t = %.4g s of %.4g (%.0f%%), step %ld, "
				"dt %.3g s, kinetic %.4g J, energy error %.2g\n",
				PROG, dem_fe_time(fe), st->end,
				100 * dem_fe_time(fe) / st->end, dem_fe_steps(fe),
				dt, en.kinetic, en.scale > 0 ? en.balance / en.scale : 0);
			next_report = dem_wall() + 2;
		}
	}
	dem_cost_time(cost, "write", twrite);
	return DEM_OK;
}

/* ---- the peening run ------------------------------------------------------ */

/* The shot stream, read a pass at a time (one row of look-ahead). */
struct shotin {
	dem_reader_t *r;
	int col[8];             /* pass t x y r vx vy vz */
	double f[8];            /* unit factors */
	double row[DEM_STREAM_MAXCOL];
	int have;               /* row holds the next pass's first row */
	dem_shot_t *sh;
	size_t n, cap;
	long pass;              /* last pass read, -1 at first */
	uLong crc;              /* CRC-32 of the rows read (SI values) */
	uint64_t rows;
};

static int shotin_open(struct shotin *in, const char *path, dem_error_t *e)
{
	static const char *const names[8] = {"pass", "t", "x", "y", "r", "vx", "vy", "vz"};
	const dem_dim_t dims[8] = {DEM_DIM_NONE, DEM_DIM_TIME, DEM_DIM_LENGTH, DEM_DIM_LENGTH,
				   DEM_DIM_LENGTH, DEM_DIM_VELOCITY, DEM_DIM_VELOCITY,
				   DEM_DIM_VELOCITY};
	int rc;

	memset(in, 0, sizeof *in);
	in->pass = -1;
	if ((rc = dem_reader_open(&in->r, path, e)))
		return rc;
	const dem_header_t *h = dem_reader_header(in->r);
	if (strcmp(h->kind, "shots"))
		return dem_error_set(e, DEM_EINPUT, "%s: a %s stream, expected a shot stream "
				     "(dempack shots)", dem_reader_name(in->r), h->kind);
	for (int i = 0; i < 8; i++) {
		in->col[i] = dem_header_col(h, names[i]);
		if (in->col[i] < 0)
			return dem_error_set(e, DEM_EINPUT, "%s: no column '%s' in the shot "
					     "stream", dem_reader_name(in->r), names[i]);
		if ((rc = dem_header_col_factor(h, in->col[i], dims[i], dem_reader_name(in->r),
						&in->f[i], e)))
			return rc;
	}
	return DEM_OK;
}

/* Read the next pass: 1 with shots in in->sh[0..n), 0 at the end. */
static int shotin_pass(struct shotin *in, dem_error_t *e)
{
	in->n = 0;
	for (;;) {
		if (!in->have) {
			int k = dem_reader_next(in->r, in->row, e);
			if (k < 0)
				return -1;
			if (k == 0)
				return in->n > 0;
			in->have = 1;
		}
		double v[8];
		for (int i = 0; i < 8; i++)
			v[i] = in->row[in->col[i]] * in->f[i];
		long pass = (long)v[0];
		if (in->n > 0 && pass != (long)in->sh[0].pass)
			return 1;       /* the row starts the next pass */
		if (pass < in->pass + (in->n == 0))
			return dem_error_set(e, DEM_EINPUT, "%s: pass %ld after pass %ld: the "
					     "passes must increase", dem_reader_where(in->r),
					     pass, in->pass), -1;
		if (in->n == in->cap) {
			size_t c = in->cap ? 2 * in->cap : 64;
			dem_shot_t *q = realloc(in->sh, c * sizeof *q);
			if (!q)
				return dem_error_nomem(e, "shots"), -1;
			in->sh = q, in->cap = c;
		}
		dem_shot_t *q = &in->sh[in->n++];
		q->pass = (unsigned long)pass;
		q->t = v[1], q->x[0] = v[2], q->x[1] = v[3], q->r = v[4];
		q->v[0] = v[5], q->v[1] = v[6], q->v[2] = v[7];
		if (!(q->r > 0) || !(q->v[2] < 0) || !(q->t >= 0))
			return dem_error_set(e, DEM_EINPUT, "%s: a shot needs r > 0, vz < 0 "
					     "(towards the block) and t >= 0", dem_reader_where(in->r)), -1;
		in->pass = pass;
		in->have = 0;
		in->crc = crc32(in->crc, (const Bytef *)v, sizeof v);
		in->rows++;
	}
}

/* The next pass on every rank: rank 0 reads it (shotin_pass) and sends
 * it to the others. */
static int shots_next(const struct blk *b, struct shotin *in, dem_error_t *e)
{
	int k = root(b) ? shotin_pass(in, e) : 0;
	if (dem_par_size(b->par) == 1)
		return k;
	long hd[3] = {k, k < 0 ? e->code : 0, (long)in->n};
	dem_par_bcast(b->par, hd, sizeof hd, 0);
	if (hd[0] < 0) {
		if (!root(b))
			dem_error_set(e, (int)hd[1], "rank 0 failed reading the shots");
		return -1;
	}
	if (!root(b) && (size_t)hd[2] > in->cap) {
		dem_shot_t *q = realloc(in->sh, (size_t)hd[2] * sizeof *q);
		if (!q)   /* the other ranks would wait for this one */
			dem_par_abort(b->par, DEM_EIO);
		in->sh = q, in->cap = (size_t)hd[2];
	}
	in->n = (size_t)hd[2];
	dem_par_bcast(b->par, in->sh, in->n * sizeof *in->sh, 0);
	return (int)hd[0];
}

static void shotin_close(struct shotin *in)
{
	dem_reader_close(in->r);
	free(in->sh);
}

/* The force history: per step, one row per shot in contact. */
static int open_forces(const char *path, int argc, char **args, dem_writer_t **w,
		       dem_error_t *e)
{
	static const char *const cols[] = {"t", "fn", "ft", "fx", "fy", "fz"};
	static const char *const units[] = {"s", "N", "N", "N", "N", "N"};
	dem_header_t h;
	int rc;

	dem_header_init(&h, "history", 1, 3);
	dem_header_add_col(&h, "pass", DEM_U32, "-");
	dem_header_add_col(&h, "shot", DEM_U32, "-");
	for (int i = 0; i < 6; i++)
		dem_header_add_col(&h, cols[i], DEM_F64, units[i]);
	dem_header_add_provenance(&h, PROG, argc, args, 0, 0);
	rc = dem_writer_open(w, path, &h, 0, e);
	dem_header_free(&h);
	return rc;
}


/* ---- checkpoints ----------------------------------------------------------

 * After each pass the run is saved in two files:
 *  - FILE.journal, appended: the frames (and force history rows) written so
 *    far, as raw doubles, so that a resumed run can write the complete
 *    output streams again (outputs are written whole, atomically, with
 *    their trailer only at the end: they cannot be appended to);
 *  - FILE, replaced atomically (temporary name, fsync, rename): a header
 *    (what the run is: the resolved scene's checksum, the shot rows read and
 *    their checksum, the passes done, the journal's length and checksum at
 *    that point) and the explicit model (dem_fe_save).
 * The journal is synced before the checkpoint names its length, so a kill
 * at any moment leaves a checkpoint whose journal prefix is complete; a
 * resumed run cuts the journal back to that length.  Shots and contact
 * states do not persist across passes (dem_shotset_begin starts afresh),
 * so the model and the position in the shot stream are the whole state. */

#define CK_VERSION 2
static const char ck_magic[8] = "DEMSHOT\x01";
enum { J_FRAME = 1, J_FORCE = 2 };

typedef struct ck_head {
	char magic[8];
	uint32_t version, scene_crc, shots_crc, forces;
	uint64_t shot_rows;
	int64_t passes;
	uint64_t jlen;
	uint32_t jcrc, pad;
	double wall_s, cpu_s;   /* what the run has spent to this checkpoint, over
				 * all the processes that made it (version 2) */
} ck_head_t;

struct ckpt {
	const char *path;
	char *jpath;
	FILE *j;                /* the journal */
	uLong jcrc;
	uint64_t jlen;
	uint32_t scene_crc;
	int forces;
	long stop_after;        /* DEMSHOT_STOP_AFTER: testing aid */
	double save_s;
	size_t size;            /* of the last checkpoint, bytes */
	double wall0, cpu0;     /* this process's start (its cost clock) */
	double wall_before, cpu_before; /* spent before it (a resumed run) */
	long passes_before;     /* the passes done before it */
};

static int ck_jwrite(struct ckpt *ck, const void *p, size_t n, dem_error_t *e)
{
	if (fwrite(p, 1, n, ck->j) != n)
		return dem_error_set(e, DEM_EIO, "%s: %s", ck->jpath, strerror(errno));
	ck->jcrc = crc32(ck->jcrc, p, (uInt)n);
	ck->jlen += n;
	return DEM_OK;
}

static int ck_frame(struct ckpt *ck, const dem_mesh_t *m, unsigned pass, double t,
		    const struct fields *f, dem_error_t *e)
{
	uint32_t tag[2] = {J_FRAME, pass};
	if (!ck)
		return DEM_OK;
	return ck_jwrite(ck, tag, sizeof tag, e) || ck_jwrite(ck, &t, sizeof t, e) ||
	       ck_jwrite(ck, f->u, 3 * m->nn * sizeof *f->u, e) ||
	       ck_jwrite(ck, f->sig, 6 * m->ne * sizeof *f->sig, e) ||
	       ck_jwrite(ck, f->eps, 6 * m->ne * sizeof *f->eps, e) ||
	       ck_jwrite(ck, f->ep, m->ne * sizeof *f->ep, e) ? e->code : DEM_OK;
}

static int ck_force(struct ckpt *ck, const double row[8], dem_error_t *e)
{
	uint32_t tag[2] = {J_FORCE, 0};
	if (!ck)
		return DEM_OK;
	return ck_jwrite(ck, tag, sizeof tag, e) || ck_jwrite(ck, row, 8 * sizeof *row, e)
	       ? e->code : DEM_OK;
}

/* The resolved scene's checksum: what the run computes from. */
static uint32_t scene_crc(const dem_scene_t *s)
{
	char *buf = NULL;
	size_t n = 0;
	FILE *f = open_memstream(&buf, &n);
	uLong c = crc32(0, Z_NULL, 0);
	if (f) {
		dem_scene_dump(s, f);
		fclose(f);
		c = crc32(c, (const Bytef *)buf, (uInt)n);
	}
	free(buf);
	return (uint32_t)c;
}

static int ck_init(struct ckpt *ck, const char *path, const dem_scene_t *s, int forces,
		   const dem_cost_t *cost, dem_error_t *e)
{
	const char *stop = getenv("DEMSHOT_STOP_AFTER");
	memset(ck, 0, sizeof *ck);
	ck->path = path;
	ck->wall0 = cost->wall0;
	ck->cpu0 = cost->cpu0;
	ck->scene_crc = scene_crc(s);
	ck->forces = forces;
	ck->stop_after = stop && *stop ? strtol(stop, NULL, 10) : -1;
	ck->jpath = malloc(strlen(path) + sizeof ".journal");
	if (!ck->jpath)
		return dem_error_nomem(e, "checkpoint");
	strcpy(ck->jpath, path);
	strcat(ck->jpath, ".journal");
	return DEM_OK;
}

/* A fresh run: no old checkpoint may name the journal being rewritten. */
static int ck_fresh(struct ckpt *ck, dem_error_t *e)
{
	if (remove(ck->path) && errno != ENOENT)
		return dem_error_set(e, DEM_EIO, "%s: %s", ck->path, strerror(errno));
	ck->j = fopen(ck->jpath, "wb");
	if (!ck->j)
		return dem_error_set(e, DEM_EIO, "%s: %s", ck->jpath, strerror(errno));
	ck->jcrc = crc32(0, Z_NULL, 0);
	ck->jlen = 0;
	return DEM_OK;
}

/* Save after a pass: sync the journal, then write FILE atomically. */
static int ck_save(struct ckpt *ck, const struct blk *b, const struct shotin *in, long passes,
		   dem_error_t *e)
{
	double t0 = dem_wall();
	ck_head_t h;
	int rc = DEM_OK;

	if (fflush(ck->j) || fsync(fileno(ck->j)))
		return dem_error_set(e, DEM_EIO, "%s: %s", ck->jpath, strerror(errno));
	memset(&h, 0, sizeof h);
	memcpy(h.magic, ck_magic, sizeof h.magic);
	h.version = CK_VERSION;
	h.scene_crc = ck->scene_crc;
	h.shots_crc = (uint32_t)in->crc;
	h.shot_rows = in->rows;
	h.forces = (uint32_t)ck->forces;
	h.passes = passes;
	h.jlen = ck->jlen;
	h.jcrc = (uint32_t)ck->jcrc;
	h.wall_s = ck->wall_before + dem_wall() - ck->wall0;
	h.cpu_s = ck->cpu_before + dem_cpu() - ck->cpu0;
	uint32_t hcrc = (uint32_t)crc32(crc32(0, Z_NULL, 0), (const Bytef *)&h, sizeof h);
	dem_afile_t af;
	if (dem_afile_open(&af, ck->path, "wb", e))
		return e->code;
	if (fwrite(&h, sizeof h, 1, af.f) != 1 || fwrite(&hcrc, sizeof hcrc, 1, af.f) != 1)
		rc = dem_error_set(e, DEM_EIO, "%s: write error", ck->path);
	else
		rc = blk_save(b, af.f, e);
	if (!rc) {
		long sz = ftell(af.f);
		ck->size = sz > 0 ? (size_t)sz : 0;
		rc = dem_afile_commit(&af, 1, e);
	} else {
		dem_afile_abort(&af);
	}
	ck->save_s += dem_wall() - t0;
	return rc;
}

/* Resume: read FILE into fe, skip the shot stream's passes done (checking
 * they are the ones the checkpoint saw), write the journal's frames and
 * force rows to the outputs again (f keeps the last frame), and cut the
 * journal back to the checkpoint.  *passes: the passes done; 0 with no
 * checkpoint (a run killed in its first pass starts again). */
static int ck_resume(struct ckpt *ck, struct blk *b, struct shotin *in, const dem_mesh_t *m,
		     dem_state_writer_t *w, dem_writer_t *fw, struct fields *fl, long *passes,
		     int quiet, dem_error_t *e)
{
	ck_head_t h;
	uint32_t hcrc;
	int rc;
	FILE *f = fopen(ck->path, "rb");

	*passes = 0;
	if (!f && errno == ENOENT) {
		fprintf(stderr, "%s: %s: no checkpoint; starting from the first pass\n", PROG,
			ck->path);
		return ck_fresh(ck, e);
	}
	if (!f)
		return dem_error_set(e, DEM_EIO, "%s: %s", ck->path, strerror(errno));
	if (fread(&h, sizeof h, 1, f) != 1 || fread(&hcrc, sizeof hcrc, 1, f) != 1) {
		fclose(f);
		return dem_error_set(e, DEM_EINPUT, "%s: truncated checkpoint", ck->path);
	}
	if (memcmp(h.magic, ck_magic, sizeof h.magic) || h.version != CK_VERSION) {
		fclose(f);
		return dem_error_set(e, DEM_EINPUT, "%s: not a demshot checkpoint of version %d%s",
				     ck->path, CK_VERSION, memcmp(h.magic, ck_magic, sizeof h.magic) ? ""
				     : " (an older demshot's: run it again without --resume)");
	}
	if (hcrc != (uint32_t)crc32(crc32(0, Z_NULL, 0), (const Bytef *)&h, sizeof h)) {
		fclose(f);
		return dem_error_set(e, DEM_EINPUT, "%s: corrupt checkpoint (header checksum)",
				     ck->path);
	}
	if (h.scene_crc != ck->scene_crc) {
		fclose(f);
		return dem_error_set(e, DEM_EINPUT, "%s: the checkpoint is of another scene (the "
				     "resolved scene's checksum is %08x, this run's %08x: see "
				     "--dump-scene)", ck->path, (unsigned)h.scene_crc,
				     (unsigned)ck->scene_crc);
	}
	if (h.forces != (uint32_t)ck->forces) {
		fclose(f);
		return dem_error_set(e, DEM_EINPUT, "%s: the checkpoint was written %s --forces; "
				     "resume %s it", ck->path, h.forces ? "with" : "without",
				     h.forces ? "with" : "without");
	}
	rc = blk_load(b, f, e);
	fclose(f);
	if (rc)
		return dem_error_set(e, rc, "%s: %s", ck->path, e->msg);
	/* the shot stream's passes done */
	for (int64_t k = 0; k < h.passes; k++) {
		int r = shotin_pass(in, e);
		if (r < 0)
			return e->code;
		if (r == 0)
			return dem_error_set(e, DEM_EINPUT, "%s: the shot stream has %lld passes; the "
					     "checkpoint %s was written after %lld", dem_reader_name(in->r),
					     (long long)k, ck->path, (long long)h.passes);
	}
	if (in->rows != h.shot_rows || (uint32_t)in->crc != h.shots_crc)
		return dem_error_set(e, DEM_EINPUT, "%s: the checkpoint %s is of another shot stream "
				     "(its first %lld passes: %llu rows, checksum %08x; here %llu rows, "
				     "%08x)", dem_reader_name(in->r), ck->path, (long long)h.passes,
				     (unsigned long long)h.shot_rows, (unsigned)h.shots_crc,
				     (unsigned long long)in->rows, (unsigned)in->crc);
	/* the frames and rows written so far */
	ck->j = fopen(ck->jpath, "r+b");
	if (!ck->j)
		return dem_error_set(e, DEM_EINPUT, "%s: %s (the checkpoint's journal)", ck->jpath,
				     strerror(errno));
	uLong c = crc32(0, Z_NULL, 0);
	uint64_t len = 0;
	size_t fsz = (3 * m->nn + 13 * m->ne) * sizeof(double);
	while (len < h.jlen) {
		uint32_t tag[2];
		double t, row[8];
		if (fread(tag, sizeof tag, 1, ck->j) != 1)
			goto short_journal;
		c = crc32(c, (const Bytef *)tag, sizeof tag);
		len += sizeof tag;
		if (tag[0] == J_FRAME) {
			if (fread(&t, sizeof t, 1, ck->j) != 1 ||
			    fread(fl->u, sizeof *fl->u, 3 * m->nn, ck->j) != 3 * m->nn ||
			    fread(fl->sig, sizeof *fl->sig, 6 * m->ne, ck->j) != 6 * m->ne ||
			    fread(fl->eps, sizeof *fl->eps, 6 * m->ne, ck->j) != 6 * m->ne ||
			    fread(fl->ep, sizeof *fl->ep, m->ne, ck->j) != m->ne)
				goto short_journal;
			c = crc32(c, (const Bytef *)&t, sizeof t);
			c = crc32(c, (const Bytef *)fl->u, (uInt)(3 * m->nn * sizeof *fl->u));
			c = crc32(c, (const Bytef *)fl->sig, (uInt)(6 * m->ne * sizeof *fl->sig));
			c = crc32(c, (const Bytef *)fl->eps, (uInt)(6 * m->ne * sizeof *fl->eps));
			c = crc32(c, (const Bytef *)fl->ep, (uInt)(m->ne * sizeof *fl->ep));
			len += sizeof t + fsz;
			if (len <= h.jlen && (rc = dem_state_write_frame(w, tag[1], t, fl->u, fl->sig,
									 fl->eps, fl->ep, e)))
				return rc;
		} else if (tag[0] == J_FORCE) {
			if (fread(row, sizeof row, 1, ck->j) != 1)
				goto short_journal;
			c = crc32(c, (const Bytef *)row, sizeof row);
			len += sizeof row;
			if (len <= h.jlen && fw && (rc = dem_writer_row(fw, row, e)))
				return rc;
		} else {
			break;
		}
	}
	if (len != h.jlen || (uint32_t)c != h.jcrc)
		return dem_error_set(e, DEM_EINPUT, "%s: corrupt journal (it does not match the "
				     "checkpoint %s)", ck->jpath, ck->path);
	if (fflush(ck->j) || ftruncate(fileno(ck->j), (off_t)len) || fseek(ck->j, 0, SEEK_END))
		return dem_error_set(e, DEM_EIO, "%s: %s", ck->jpath, strerror(errno));
	ck->jcrc = c;
	ck->jlen = len;
	ck->wall_before = h.wall_s;
	ck->cpu_before = h.cpu_s;
	ck->passes_before = (long)h.passes;
	*passes = (long)h.passes;
	if (!quiet)
		fprintf(stderr, "%s: resuming after pass %ld (%lld passes done) at t = %.4g s\n",
			PROG, in->pass, (long long)h.passes, blk_time(b));
	return DEM_OK;
short_journal:
	return dem_error_set(e, DEM_EINPUT, "%s: truncated journal (the checkpoint %s names %llu "
			     "bytes)", ck->jpath, ck->path, (unsigned long long)h.jlen);
}

static void ck_close(struct ckpt *ck, int ok)
{
	if (ck->j)
		fclose(ck->j);
	ck->j = NULL;
	/* a finished run's outputs are complete: its checkpoint has done its
	 * job; a failed one keeps its last checkpoint to resume from, and
	 * with none the journal is of no use (a run that fails in its first
	 * pass, a disk full before the first save) */
	if (ok) {
		remove(ck->path);
		remove(ck->jpath);
	} else if (access(ck->path, F_OK) != 0 && errno == ENOENT) {
		remove(ck->jpath);
	}
	free(ck->jpath);
	ck->jpath = NULL;
}

/* One pass: place the shots, step until steady or the pass time, write
 * the frame. */
static int run_pass(struct blk *b, const struct settings *st,
		    const struct shotin *in, int quiet, dem_state_writer_t *w,
		    dem_writer_t *fw, struct fields *f, struct ckpt *ck, double *next_report,
		    dem_error_t *e)
{
	double t0 = blk_time(b), peak = 0;
	unsigned pass = (unsigned)in->sh[0].pass;
	int rc, wrc = 0;   /* several ranks: rank 0's write error, for the pass's end */

	if ((rc = sh_begin(b, in->n, in->sh, e)))
		return rc;
	for (;;) {
		double dt, t = blk_time(b);
		if ((rc = sh_prepare(b, &dt, e)) || (rc = blk_step(b, dt, e)))
			return rc;
		if (fw && !wrc) {
			for (size_t i = 0; i < sh_count(b) && !wrc; i++) {
				const dem_shot_body_t *s = sh_body(b, i);
				if (!s->contacts)
					continue;
				/* 2D: the plane is the stream's x-z plane */
				double row[8] = {pass, (double)i, t - t0, s->Fn, s->Ft, s->F[0],
						 b->fe2 ? 0 : s->F[1], s->F[b->fe2 ? 1 : 2]};
				if ((wrc = dem_writer_row(fw, row, e)) || (wrc = ck_force(ck, row, e)))
					if (dem_par_size(b->par) == 1)
						return wrc;
			}
		}
		dem_fe_energy_t en;
		blk_energy(b, &en);
		peak = fmax(peak, en.kinetic);
		if (sh_done(b) && en.kinetic <= st->steady * peak)
			break;
		if (blk_time(b) - t0 >= st->pass_time) {
			if (!quiet) {
				size_t touch, coming;
				char why[96] = "";
				if (sh_holding(b, &touch, &coming) > 0)
					snprintf(why, sizeof why, "; shots: %zu in contact, %zu moving "
						 "down out of contact", touch, coming);
				fprintf(stderr, "%s: pass %u: not steady after %g s (kinetic "
					"energy %.3g of its peak%s); ending it\n", PROG, pass,
					st->pass_time, peak > 0 ? en.kinetic / peak : 0, why);
			}
			break;
		}
		if (!quiet && dem_wall() > *next_report) {
			fprintf(stderr, "%s: pass %u: t = %.4g s, step %ld, dt %.3g s, "
				"kinetic %.4g J (%.2g of peak)\n", PROG, pass,
				blk_time(b) - t0, blk_steps(b), dt, en.kinetic,
				peak > 0 ? en.kinetic / peak : 0);
			*next_report = dem_wall() + 2;
		}
	}
	fields_get(b, f);
	if (root(b) && !(rc = wrc) &&
	    !(rc = dem_state_write_frame(w, pass, blk_time(b), f->u, f->sig, f->eps, f->ep, e)))
		rc = ck_frame(ck, &st->mesh, pass, blk_time(b), f, e);
	return agree(b->par, rc, e);
}

static int run_shots(struct blk *b, const struct settings *st,
		     struct shotin *in, int quiet, dem_state_writer_t *w, dem_writer_t *fw,
		     struct fields *f, struct ckpt *ck, long *passes, dem_error_t *e)
{
	double next_report = dem_wall() + 2;
	int k, rc;
	/* rank 0 alone keeps the checkpoint; every rank agrees on its saves */
	int saving = dem_par_max_int(b->par, ck != NULL);

	/* *passes: those done before (a resumed run) */
	while ((k = shots_next(b, in, e)) > 0) {
		if ((rc = run_pass(b, st, in, quiet, w, fw, f, ck, &next_report, e)))
			return rc;
		++*passes;
		if (!quiet)
			fprintf(stderr, "%s: pass %lu done at t = %.4g s\n", PROG,
				in->sh[0].pass, blk_time(b));
		/* the model was gathered for the frame: rank 0 holds it all */
		if (saving && (rc = agree(b->par, ck ? ck_save(ck, b, in, *passes, e) : 0, e)))
			return rc;
		if (ck && ck->stop_after == *passes) {
			/* the testing aid: die as a killed run would, leaving
			 * everything as it is */
			fprintf(stderr, "%s: DEMSHOT_STOP_AFTER=%ld: killing myself\n", PROG,
				ck->stop_after);
			fflush(NULL);
			raise(SIGKILL);
		}
	}
	if (k < 0)
		return e->code;
	if (*passes == 0)
		return dem_error_set(e, DEM_EINPUT, "%s: no shots", root(b) ? dem_reader_name(in->r) : "shots");
	return DEM_OK;
}

/* A run: the block and its model, the shots, the outputs. */
struct job {
	dem_scene_t *scene;     /* kept: the checkpoint records it */
	struct settings st;
	struct fields f;
	struct blk b;           /* the model and its shots, 3D or 2D */
	struct shotin in;
	struct ckpt ck;
	int have_in, have_ck;
	dem_state_writer_t *w;
	dem_writer_t *fw;
	dem_fe_stats_t fs0;     /* a resumed run's model: the work before */
	long passes;
	double run_s;
	/* a DE-only run (a scene with bodies) */
	int bodies;
	unsigned long seed;
	dem_de_setup_t su;
	dem_de_t de;
	gsl_rng *rng;
	dem_writer_t *bw;
};

static void job_free(struct job *j, int failed)
{
	if (j->bodies) {
		if (failed)
			dem_writer_abort(j->bw);
		dem_de_setup_free(&j->su, &j->de);
		gsl_rng_free(j->rng);
	}
	if (failed) {
		dem_state_writer_abort(j->w);
		dem_writer_abort(j->fw);
		if (j->have_ck)
			ck_close(&j->ck, 0);
	}
	if (j->have_in)
		shotin_close(&j->in);
	dem_shotset_free(j->b.S);
	dem_shotset2d_free(j->b.S2);
	fields_free(&j->f);
	dem_fe_free(j->b.fe);
	dem_fe2_free(j->b.fe2);
	settings_free(&j->st);
	dem_scene_free(j->scene);
}

/* The scene's settings with the options' overrides; --dump-scene prints
 * them. */
static int get_settings(const struct cmdline *cl, struct job *j, dem_error_t *e)
{
	int rc;

	if ((rc = dem_scene_open(&j->scene, &cl->com, e)))
		return rc;
	j->bodies = dem_scene_has(j->scene, "bodies");
	if (j->bodies) {
		int have_seed = cl->com.have_seed;
		unsigned long seed = cl->com.seed;
		if (!(j->rng = dem_rng_new(&have_seed, &seed)))
			return dem_error_nomem(e, "random numbers");
		j->seed = seed;
		rc = dem_de_setup_read(j->scene, cl->com.accuracy, j->rng, &j->su, &j->de, e);
		if (!rc)
			rc = dem_scene_check(j->scene, dem_de_sections, e);
	} else {
		rc = read_scene(j->scene, cl->com.accuracy, cl->shots != NULL, &j->st, e);
	}
	if (rc)
		return rc;
	if (cl->com.dump)
		dem_scene_dump(j->scene, stdout);
	return DEM_OK;
}

/* The shot stream, when the scene has shots: its time step checked
 * first (Box 3.1: lambda 0.1-0.3, Eq. 3.84, refused above 0.5). */
static int open_shots(const struct cmdline *cl, struct job *j, dem_error_t *e)
{
	struct settings *st = &j->st;
	char msg[256];
	int rc;

	if (!st->have_shots && (cl->forces || cl->checkpoint))
		return dem_error_set(e, DEM_EUSAGE, "%s needs shots (a shot stream)",
				     cl->forces ? "--forces" : "--checkpoint");
	if (!st->have_shots)
		return DEM_OK;
	switch (dem_dt_lambda_check(st->so.lambda, cl->force, msg, sizeof msg)) {
	case DEM_LAMBDA_OK:
		break;
	case DEM_LAMBDA_WARN:
	case DEM_LAMBDA_FORCED:
		fprintf(stderr, "%s: warning: %s\n", PROG, msg);
		break;
	case DEM_LAMBDA_REFUSED:
		return dem_error_set(e, DEM_EUSAGE, "%s", msg);
	default:
		return dem_error_set(e, DEM_EINPUT, "%s", msg);
	}
	j->have_in = 1;
	if (dem_par_rank(j->b.par) != 0) {
		/* rank 0 reads the stream (shots_next) */
		memset(&j->in, 0, sizeof j->in);
		j->in.pass = -1;
		return DEM_OK;
	}
	if ((rc = shotin_open(&j->in, cl->shots && strcmp(cl->shots, "-") ? cl->shots : NULL, e)))
		return rc;
	const char *a = dem_header_get(dem_reader_header(j->in.r), "area");
	st->have_area = a && sscanf(a, "%lf %lf %lf %lf", &st->area[0], &st->area[1],
				    &st->area[2], &st->area[3]) == 4;
	return DEM_OK;
}

/* The 2D block's model (explicit2d.h, the options of the 3D one) and its
 * shots (shotset2d.h). */
static int build2(struct job *j, dem_error_t *e)
{
	struct settings *st = &j->st;
	dem_fe2_opts_t o;
	int rc;

	dem_fe2_opts_default(&o);
	o.mode = st->axisym ? DEM_QUAD4_AXISYM : DEM_QUAD4_PLANE;
	o.thick = st->axisym ? 1 : st->thick;
	o.rule = st->fe.rule;
	o.large = st->fe.large;
	o.dt_factor = st->fe.dt_factor;
	o.damping = st->fe.damping;
	o.hg_stiff = st->fe.hg_stiff;
	o.hg_visc = st->fe.hg_visc;
	o.hg_tangent = st->fe.hg_tangent;
	j->b.m2 = &st->mesh2;
	if ((rc = dem_fe2_create(&j->b.fe2, &st->mesh2, &st->mat, &o, e)))
		return rc;
	dem_feshot2d_opts_t fo = {
		.element = st->fe_element, .E = st->fe_ratio * st->mat.E, .nu = st->mat.nu,
		.rho = st->so.rho, .fe = o
	};
	dem_shotset2d_opts_t so = {
		.mode = o.mode, .thick = o.thick, .rho = st->so.rho,
		.lambda = st->so.lambda, .gap = st->so.gap, .fe = st->fe_shot ? &fo : NULL
	};
	if ((rc = dem_shotset2d_create(&j->b.S2, &st->mesh2, dem_fe2_mass(j->b.fe2), &st->cm,
				       &so, e)))
		return rc;
	dem_fe2_set_load(j->b.fe2, dem_shotset2d_hook, j->b.S2);
	return DEM_OK;
}

/* The block's model, its load or its shots, and the fields it writes;
 * the setup's time counts from t0. */
static int build(const struct cmdline *cl, struct job *j, double t0, dem_cost_t *cost,
		 dem_error_t *e)
{
	struct settings *st = &j->st;
	int rc;

	if (st->dim == 2 && (rc = build2(j, e)))
		return rc;
	st->fe.par = j->b.par;
	if (st->dim == 3 &&
	    ((rc = dem_fe_create(&j->b.fe, &st->mesh, &st->mat, &st->fe, e)) ||
	     (st->have_load && (rc = apply_load(j->b.fe, st, e)))))
		return rc;
	if (st->dim == 3 && st->have_shots) {
		if ((rc = dem_shotset_create(&j->b.S, &st->mesh, dem_fe_mass(j->b.fe), &st->cm, &st->so, e)))
			return rc;
		size_t n0, n1;
		dem_fe_set_load(j->b.fe, dem_shotset_hook, j->b.S);
		dem_shotset_nodes(j->b.S, &n0, &n1);
		dem_fe_set_load_nodes(j->b.fe, n0, n1);
	}
	if (fields_alloc(&j->f, st))
		return dem_error_nomem(e, "fields");
	dem_cost_time(cost, "setup", dem_wall() - t0);
	if (!cl->com.quiet || cl->com.verbose) {
		if (st->dim == 2)
			fprintf(stderr, "%s: 2D %s block of %zu elements (%d x %d), %zu "
				"nodes; stable step %.3g s\n", PROG, st->axisym ? "axisymmetric" :
				"plane strain", st->mesh2.ne, st->mesh2.nx, st->mesh2.ny,
				st->mesh2.nn, blk_dt(&j->b));
		else
			fprintf(stderr, "%s: block of %zu elements (%d x %d x %d), %zu "
				"nodes; stable step %.3g s\n", PROG, st->mesh.ne, st->mesh.nx,
				st->mesh.ny, st->mesh.nz, st->mesh.nn, blk_dt(&j->b));
		log_effects(st);
	}
	return DEM_OK;
}

/* The state stream, the force history, and the checkpoint (a fresh one,
 * or the run so far restored from it with --resume). */
static int open_outputs(const struct cmdline *cl, struct job *j, const dem_main_t *r,
			dem_error_t *e)
{
	int rc;

	if (dem_par_rank(j->b.par) != 0)
		return DEM_OK;   /* rank 0 writes */
	if ((rc = open_state(cl, &j->st, r->argc, r->args, &j->w, e)) ||
	    (cl->forces && (rc = open_forces(cl->forces, r->argc, r->args, &j->fw, e))))
		return rc;
	if (!cl->checkpoint)
		return DEM_OK;
	j->have_ck = 1;
	if ((rc = ck_init(&j->ck, cl->checkpoint, j->scene, cl->forces != NULL, &r->cost, e)) ||
	    (rc = cl->resume ? ck_resume(&j->ck, &j->b, &j->in, &j->st.mesh, j->w, j->fw, &j->f,
					 &j->passes, cl->com.quiet, e)
			     : ck_fresh(&j->ck, e)))
		return rc;
	blk_stats(&j->b, &j->fs0);
	return DEM_OK;
}

/* The time loop (shots pass by pass, or the pressure pulse), then the
 * outputs closed and the last state for ParaView. */
static int run_job(const struct cmdline *cl, struct job *j, dem_cost_t *cost, dem_error_t *e)
{
	struct settings *st = &j->st;
	double t = dem_wall();
	int rc;

	if (st->have_shots)
		rc = run_shots(&j->b, st, &j->in, cl->com.quiet, j->w, j->fw, &j->f,
			       j->have_ck ? &j->ck : NULL, &j->passes, e);
	else
		rc = run(&j->b, st, cl->com.quiet, j->w, &j->f, cost, e);
	if (rc)
		return rc;
	j->run_s = dem_wall() - t;
	dem_cost_time(cost, "run", j->run_s);
	rc = j->w ? dem_state_writer_close(j->w, e) : 0;
	j->w = NULL;
	if (!rc && j->fw) {
		rc = dem_writer_close(j->fw, e);
		j->fw = NULL;
	}
	if ((rc = agree(j->b.par, rc, e)))
		return rc;
	if (j->have_ck) {
		dem_cost_time(cost, "checkpoint", j->ck.save_s);
		dem_cost_count(cost, "checkpoint_mb", (double)j->ck.size / 1048576);
		if (j->ck.passes_before > 0) {
			/* a resumed run: what the whole run spent, this process
			 * and the ones that wrote its checkpoints (not the work a
			 * killed process did after its last checkpoint) */
			dem_cost_count(cost, "resumed_after", (double)j->ck.passes_before);
			dem_cost_time(cost, "total_wall", j->ck.wall_before + dem_wall() - j->ck.wall0);
			dem_cost_time(cost, "total_cpu", j->ck.cpu_before + dem_cpu() - j->ck.cpu0);
		}
		ck_close(&j->ck, 1);
		j->have_ck = 0;
	}
	if (cl->vtu && dem_par_rank(j->b.par) == 0)
		return dem_vtu_write(cl->vtu, &st->mesh,
				     &(dem_vtu_fields_t){j->f.u, j->f.sig, j->f.eps, j->f.ep}, 1, e);
	return DEM_OK;
}

/* The energies (-v), the share of the time per effect (DESIGN.md
 * "Effects") and the cost line's counters. */
static void report(const struct cmdline *cl, const struct job *j, dem_cost_t *cost)
{
	const struct settings *st = &j->st;
	const double run_s = j->run_s;
	dem_fe_energy_t en;
	dem_fe_stats_t fs;

	blk_energy(&j->b, &en);
	blk_stats(&j->b, &fs);
	/* this process's work (steps stay the run's) */
	fs.elem_s -= j->fs0.elem_s, fs.node_s -= j->fs0.node_s, fs.elem_cycles -= j->fs0.elem_cycles;
	if (cl->com.verbose)
		fprintf(stderr, "%s: energies at t = %.6g s (J): kinetic %.6g, "
			"internal %.6g (plastic %.6g), hourglass %.6g, damping "
			"%.6g, external %.6g; balance %.3g\n", PROG, en.t,
			en.kinetic, en.internal, en.plastic, en.hourglass,
			en.damping, en.external, en.balance);
	dem_cost_time(cost, "element_loop", fs.elem_s);
	dem_cost_time(cost, "node_loop", fs.node_s);
	if (dem_par_size(j->b.par) > 1 && j->b.fe) {
		/* rank 0's: its exchanges with the other ranks, and its bytes
		 * sent a step (examples/cost: the communication model) */
		dem_cost_time(cost, "exchange", fs.comm_s);
		dem_cost_count(cost, "ranks", dem_par_size(j->b.par));
		dem_cost_count(cost, "bytes_per_step", dem_fe_comm_bytes(j->b.fe));
	}
	dem_cost_count(cost, "steps", (double)fs.steps);
	dem_cost_count(cost, "elements", (double)st->mesh.ne);
	dem_cost_count(cost, "elem_cycles", fs.elem_cycles);
	dem_cost_count(cost, "ns_per_elem_cycle",
		       fs.elem_cycles > 0 ? 1e9 * (fs.elem_s + fs.node_s) / fs.elem_cycles : 0);
	dem_cost_count(cost, "energy_error", en.scale > 0 ? fabs(en.balance) / en.scale : 0);
	if (!j->b.S && !j->b.S2)
		return;
	const dem_feshot2d_t *F = j->b.S2 ? dem_shotset2d_feshot(j->b.S2) : NULL;
	if (F && dem_feshot2d_model(F))
		dem_cost_count(cost, "shot_elements", (double)dem_feshot2d_mesh(F)->ne);
	dem_shotset_stats_t ss;
	sh_stats(&j->b, &ss);
	if (!cl->com.quiet && run_s > 0)
		fprintf(stderr, "%s: time: elements %.0f%%, contact (%s) %.0f%%, "
			"candidates %.0f%%, shot motion %.0f%%, other %.0f%%\n", PROG,
			100 * (fs.elem_s + fs.node_s) / run_s, st->cm.effects,
			100 * ss.contact_s / run_s, 100 * ss.detect_s / run_s,
			100 * ss.integrate_s / run_s, 100 * (run_s - fs.elem_s - fs.node_s
			- ss.contact_s - ss.detect_s - ss.integrate_s) / run_s);
	dem_cost_time(cost, "contact", ss.contact_s);
	dem_cost_time(cost, "detect", ss.detect_s);
	dem_cost_count(cost, "passes", (double)j->passes);
	dem_cost_count(cost, "rebuilds", (double)ss.rebuilds);
	dem_cost_count(cost, "contacts", ss.contacts);
	dem_cost_count(cost, "ns_per_contact",
		       ss.contacts > 0 ? 1e9 * ss.contact_s / ss.contacts : 0);
}

/* ---- the DE-only run ------------------------------------------------------- */

/* The bodies of the scene to run.end, the body stream a frame at a time
 * (the start's, then run.frames evenly spaced; each at the step nearest
 * its time), the last frame as VTK polygons with --vtu; the cost line's
 * phases and counters. */
static int run_bodies(const struct cmdline *cl, struct job *j, const dem_main_t *r,
		      dem_cost_t *cost, dem_error_t *e)
{
	dem_de_t *de = &j->de;
	const dem_de_setup_t *su = &j->su;
	int flags = (cl->com.binary ? DEM_STREAM_BINARY : 0) | (cl->com.gzip ? DEM_STREAM_GZIP : 0);
	double next_report = dem_wall() + 2, t0 = dem_wall();
	char fx[160];
	int rc;

	if (cl->shots || cl->forces || cl->checkpoint)
		return dem_error_set(e, DEM_EUSAGE, "%s: a scene with bodies is a DE-only run "
				     "(no shots, forces or checkpoint)", cl->shots ? cl->shots :
				     cl->forces ? "--forces" : "--checkpoint");
	if ((rc = dem_de_start(de, e)))
		return rc;
	dem_cost_time(cost, "setup", dem_wall() - t0);
	if (!cl->com.quiet || cl->com.verbose)
		fprintf(stderr, "%s: %zu %s bodies (%d points, %.4g kg/m each), %zu walls; "
			"step %.3g s (lambda %g, v0 %.3g m/s); effects: %s\n", PROG, de->n,
			dem_shape_kind_name(su->shape.kind), su->shape.nv, de->n ? de->mass[0] : 0,
			de->nw, de->dt, de->p.lambda, de->p.v0, dem_de_effects(de, fx, sizeof fx));
	if ((rc = dem_bodies_writer_open(&j->bw, cl->com.output, de, PROG, r->argc, r->args, 1,
					 j->seed, flags, e)) ||
	    (rc = dem_bodies_write_frame(j->bw, de, 0, e)))
		return rc;
	t0 = dem_wall();
	double c0 = dem_cpu();
	for (long k = 1; k <= su->frames; k++) {
		double tf = su->end * (double)k / (double)su->frames;
		while (de->t + 0.5 * de->dt < tf) {
			if ((rc = dem_de_step(de, e)))
				return rc;
			if (!cl->com.quiet && dem_wall() > next_report) {
				fprintf(stderr, "%s: t = %.4g s of %.4g (%.0f%%), step %ld, %zu "
					"contacts\n", PROG, de->t, su->end, 100 * de->t / su->end,
					de->steps, de->ncontact);
				next_report = dem_wall() + 2;
			}
		}
		if ((rc = dem_bodies_write_frame(j->bw, de, (unsigned)k, e)))
			return rc;
	}
	j->run_s = dem_wall() - t0;
	double run_cpu = dem_cpu() - c0;   /* the phases' clock */
	rc = dem_writer_close(j->bw, e);
	j->bw = NULL;
	if (!rc && cl->vtu)
		rc = dem_bodies_vtu(cl->vtu, de, e);
	if (rc)
		return rc;
	/* the cost of the shape: contacts resolved a second */
	dem_cost_time(cost, "run", j->run_s);
	dem_cost_time(cost, "detect", de->st.detect_s);
	dem_cost_time(cost, "contact", de->st.contact_s);
	dem_cost_time(cost, "move", de->st.move_s);
	dem_cost_count(cost, "steps", (double)de->steps);
	dem_cost_count(cost, "bodies", (double)de->n);
	dem_cost_count(cost, "points", (double)su->shape.nv);
	dem_cost_count(cost, "candidates", (double)de->st.candidates);
	dem_cost_count(cost, "contacts", (double)de->st.contacts);
	dem_cost_count(cost, "overlap_max", de->st.overlap_max);
	dem_cost_count(cost, "contacts_per_s",
		       de->st.contact_s > 0 ? floor(de->st.contacts / de->st.contact_s) : 0);
	if (!cl->com.quiet && run_cpu > 0)
		fprintf(stderr, "%s: CPU time: contact %.0f%%, candidates %.0f%%, motion %.0f%%, "
			"other %.0f%%\n", PROG, 100 * de->st.contact_s / run_cpu,
			100 * de->st.detect_s / run_cpu, 100 * de->st.move_s / run_cpu,
			100 * (run_cpu - de->st.contact_s - de->st.detect_s - de->st.move_s) /
			run_cpu);
	return DEM_OK;
}

/* What several ranks cannot run yet: the 2D block, the DE-only run, a
 * resumed run (resume it with one rank: the checkpoint holds the whole
 * model). */
static int ranks_check(const struct cmdline *cl, const struct job *j, dem_error_t *e)
{
	int np = dem_par_size(j->b.par);
	if (np == 1)
		return DEM_OK;
	if (j->bodies || j->st.dim == 2)
		return dem_error_set(e, DEM_EUSAGE, "%s runs on one rank only, not %d (MPI: the 3D "
				     "block alone)", j->bodies ? "a scene with bodies" : "the 2D block", np);
	if (cl->resume)
		return dem_error_set(e, DEM_EUSAGE, "--resume with %d ranks: not supported yet; "
				     "resume with one (mpirun -np 1, or the serial demshot)", np);
	return DEM_OK;
}

int main(int argc, char **argv)
{
	struct cmdline cl;
	struct job j = {0};
	dem_main_t r;
	dem_par_t *par;
	int rc;

	dem_error_t pe = {0};
	if ((rc = dem_par_init(&par, &argc, &argv, &pe))) {
		fprintf(stderr, "%s: %s\n", PROG, pe.msg);
		return rc;
	}
	/* rank 0 speaks; the others write nothing (their failures show in
	 * the exit status) */
	if (dem_par_rank(par) != 0 &&
	    (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr)))
		dem_par_abort(par, DEM_EIO);
	j.b.par = par;
	if ((rc = dem_main_start(&r, PROG, argc, argv))) {
		dem_par_finalize(par);
		return rc;
	}
	if ((rc = parse_cmdline(argc, argv, &cl)) >= 0) {
		rc = dem_main_quit(&r, &cl.com, rc);
		dem_par_finalize(par);
		return rc;
	}
#ifdef _OPENMP
	if (cl.threads)
		omp_set_num_threads((int)cl.threads);
#endif
	double t0 = dem_wall();
	if (!(rc = get_settings(&cl, &j, &r.e)) && !(rc = ranks_check(&cl, &j, &r.e)) &&
	    !cl.com.dump && j.bodies)
		rc = run_bodies(&cl, &j, &r, &r.cost, &r.e);
	else if (!rc && !cl.com.dump &&
	    !(rc = agree(par, open_shots(&cl, &j, &r.e), &r.e)) &&
	    !(rc = agree(par, build(&cl, &j, t0, &r.cost, &r.e), &r.e)) &&
	    !(rc = agree(par, open_outputs(&cl, &j, &r, &r.e), &r.e)) &&
	    !(rc = run_job(&cl, &j, &r.cost, &r.e)))
		report(&cl, &j, &r.cost);
	job_free(&j, rc != 0);
	rc = dem_main_end(&r, &cl.com, rc);
	dem_par_finalize(par);
	return rc;
}
