/* demshot - the explicit finite element run of the peened block.
 *
 *   demshot [OPTION]...
 *
 * Builds the block of the scene (graded hex8 mesh, face conditions, the J2
 * material), loads it and integrates it in time with the central difference
 * method (lib/fe/explicit), and writes the state stream: the mesh, then the
 * displacements and element fields at the requested frames.  This first
 * form loads the block by pressure pulses on its top face (the `load`
 * section: the usual model of laser peening, and the test load of the
 * explicit stage); the shots of a shot stream come with the contact stage.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "core/cli.h"
#include "core/cost.h"
#include "fe/explicit.h"
#include "fe/fescene.h"
#include "io/scene.h"
#include "io/state.h"
#include "io/vtu.h"

#define PROG "demshot"

enum { OPT_END = DEM_OPT_PROGRAM, OPT_FRAMES, OPT_VTU, OPT_RULE, OPT_STRAIN,
       OPT_DAMPING, OPT_DT_FACTOR, OPT_THREADS };

static const dem_opt_t options[] = {
	{"end", OPT_END, "T", "simulated time, with a unit if wanted (20us)"},
	{"frames", OPT_FRAMES, "N", "state frames, evenly spaced, the last at the end (default 1)"},
	{"rule", OPT_RULE, "RULE", "one_point (hourglass control) or full (2x2x2, B-bar)"},
	{"strain", OPT_STRAIN, "KIND", "large (updated Lagrangian, Jaumann rate) or small"},
	{"damping", OPT_DAMPING, "XI", "mass-proportional damping: ratio of critical in the lowest mode (Ch. 7.5: 0.05)"},
	{"dt-factor", OPT_DT_FACTOR, "F", "time step over the stable element step, in (0, 1] (default 0.9)"},
	{"vtu", OPT_VTU, "FILE", "also write the last frame to FILE for ParaView"},
	{"threads", OPT_THREADS, "N", "OpenMP threads for the element loop (default: OMP_NUM_THREADS or all)"},
	DEM_OPTS_COMMON,
	{0}
};

static const char usage[] = "Usage: demshot [OPTION]...\n";
static const char purpose[] =
	"Integrate the peened block of the scene in time (explicit finite elements)\n"
	"under the scene's loads and write its state stream (mesh, then displacements\n"
	"and element fields per frame; binary, gzip-compressed) to standard output.\n";
static const char epilogue[] =
	"Examples:\n"
	"  demshot -s pulse.yaml --frames 4 -o pulse.state\n"
	"  demshot -s pulse.yaml --end 5us --rule full --vtu pulse.vtu | demprofile\n"
	"\nSee demshot(1), dem-scene(5) and dem-streams(5).\n";

struct cmdline {
	dem_common_t com;
	const char *vtu;
	unsigned long threads;
};

static int parse_cmdline(int argc, char **argv, struct cmdline *cl)
{
	dem_cli_t c;
	dem_common_t *m = &cl->com;
	int k, done;

	memset(cl, 0, sizeof *cl);
	if (dem_common_init(m, argc) ||
	    dem_cli_init(&c, PROG, options, usage, purpose, epilogue))
		return DEM_EIO;
	while ((k = dem_cli_next(&c, argc, argv)) != -1) {
		if (dem_cli_common(&c, k, optarg, m))
			continue;
		switch (k) {
		case OPT_END: dem_common_override(m, "run.end", optarg, "--end"); break;
		case OPT_FRAMES: dem_common_override(m, "run.frames", optarg, "--frames"); break;
		case OPT_RULE: dem_common_override(m, "run.rule", optarg, "--rule"); break;
		case OPT_STRAIN: dem_common_override(m, "run.strain", optarg, "--strain"); break;
		case OPT_DAMPING: dem_common_override(m, "run.damping", optarg, "--damping"); break;
		case OPT_DT_FACTOR: dem_common_override(m, "run.dt_factor", optarg, "--dt-factor"); break;
		case OPT_VTU: cl->vtu = optarg; break;
		case OPT_THREADS:
			dem_cli_ulong(&c, "--threads", optarg, 1, 1024, &cl->threads);
			break;
		default: break;
		}
	}
	done = c.done;
	if (done < 0) {
		if (optind < argc)
			dem_cli_error(&c, "unexpected argument '%s'", argv[optind]);
		if (dem_cli_finish(&c))
			done = DEM_EUSAGE;
	}
	dem_cli_free(&c);
	return done;
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
	dem_mesh_t mesh;
	dem_fe_opts_t fe;
	double end, xi;         /* xi < 0: no damping */
	long frames;
	int have_load;
	struct pulse load;
};

static void settings_free(struct settings *st)
{
	dem_mat_free(&st->mat);
	dem_mesh_free(&st->mesh);
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

static int read_scene(dem_scene_t *s, int accuracy, struct settings *st,
		      dem_error_t *e)
{
	static const char *const sections[] = {"material", "block", "run", "load", NULL};
	static const char *const rules[] = {"one_point", "full", NULL};
	static const char *const strains[] = {"small", "large", NULL};
	int rule, large;

	dem_fe_opts_default(&st->fe);
	st->xi = -1;
	if (dem_scene_material(s, 1, &st->mat, e) ||
	    dem_scene_block(s, &st->mesh, e))
		return e->code;
	/* the accuracy preset chooses the element and the strain measure
	 * unless the scene does */
	if (dem_scene_choice(s, "run.rule", rules,
			     accuracy == DEM_ACCURACY_FINE ? 1 : 0, &rule, e) ||
	    dem_scene_choice(s, "run.strain", strains,
			     accuracy == DEM_ACCURACY_COARSE ? 0 : 1, &large, e) ||
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
	if (isnan(st->end))
		return dem_scene_error(s, "run.end", e, "missing: how long to "
				       "run (e.g. 20 us)");
	if (isnan(st->xi))
		st->xi = -1;    /* no damping: the effect is absent */
	else
		st->fe.damping = dem_fe_damping_alpha(&st->mat, st->xi,
						      -st->mesh.gz[0]);
	if (read_load(s, st, e))
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
		fprintf(stderr, " (%s hardening)", m->nhard > 1 ? "table" : "linear");
	if (m->flags & DEM_MAT_RATE)
		fprintf(stderr, ", rate dependence (m = %g)", m->rate_m);
	fprintf(stderr, ", %s strain, %s", st->fe.large ? "large" : "small",
		st->fe.rule == DEM_FE_FULL ? "full 2x2x2 B-bar integration"
		: "one-point integration with hourglass control");
	if (st->xi >= 0)
		fprintf(stderr, ", damping %g of critical", st->xi);
	fprintf(stderr, "%s\n", st->have_load ? ", pressure load" : "");
}

/* Field buffers for a frame. */
struct fields {
	double *u, *sig, *eps, *ep;
};

static int fields_alloc(struct fields *f, const dem_mesh_t *m)
{
	f->u = malloc(3 * m->nn * sizeof *f->u);
	f->sig = malloc(6 * m->ne * sizeof *f->sig);
	f->eps = malloc(6 * m->ne * sizeof *f->eps);
	f->ep = malloc(m->ne * sizeof *f->ep);
	return f->u && f->sig && f->eps && f->ep ? 0 : -1;
}

static void fields_free(struct fields *f)
{
	free(f->u), free(f->sig), free(f->eps), free(f->ep);
}

static void fields_get(const dem_fe_t *fe, struct fields *f)
{
	dem_fe_displacements(fe, f->u);
	dem_fe_fields(fe, f->sig, f->eps, f->ep);
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
			   st->xi >= 0 ? st->xi : 0)) {
		dem_header_free(&h);
		return dem_error_nomem(e, "header");
	}
	rc = dem_state_writer_open(w, cl->com.output, m, &h, DEM_STATE_FLAGS, e);
	dem_header_free(&h);
	return rc;
}

/* Run to the end, writing the frames; progress on stderr every 2 s. */
static int run(dem_fe_t *fe, const struct settings *st, int quiet,
	       dem_state_writer_t *w, struct fields *f, dem_cost_t *cost,
	       dem_error_t *e)
{
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
			fields_get(fe, f);
			if ((rc = dem_state_write_frame(w, 1, dem_fe_time(fe), f->u,
							f->sig, f->eps, f->ep, e)))
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

int main(int argc, char **argv)
{
	struct cmdline cl;
	struct settings st = {0};
	struct fields f = {0};
	dem_error_t e = {0};
	dem_scene_t *scene = NULL;
	dem_fe_t *fe = NULL;
	dem_state_writer_t *w = NULL;
	dem_cost_t cost;
	int rc;

	dem_cost_start(&cost);
	char **args = malloc(((size_t)argc + 1) * sizeof *args);
	if (!args)
		return DEM_EIO;
	memcpy(args, argv, ((size_t)argc + 1) * sizeof *args);
	if ((rc = parse_cmdline(argc, argv, &cl)) >= 0) {
		free(args);
		dem_common_free(&cl.com);
		return rc;
	}
#ifdef _OPENMP
	if (cl.threads)
		omp_set_num_threads((int)cl.threads);
#endif
	double t = dem_wall();
	if ((rc = dem_scene_load(&scene, cl.com.scene, &e)) ||
	    (rc = dem_scene_override_all(scene, cl.com.ov, cl.com.nov, &e)) ||
	    (rc = read_scene(scene, cl.com.accuracy, &st, &e)))
		goto fail;
	if (cl.com.dump) {
		dem_scene_dump(scene, stdout);
		goto done;
	}
	if ((rc = dem_fe_create(&fe, &st.mesh, &st.mat, &st.fe, &e)) ||
	    (st.have_load && (rc = apply_load(fe, &st, &e))))
		goto fail;
	if (fields_alloc(&f, &st.mesh)) {
		rc = dem_error_nomem(&e, "fields");
		goto fail;
	}
	dem_cost_time(&cost, "setup", dem_wall() - t);
	if (!cl.com.quiet || cl.com.verbose) {
		fprintf(stderr, "%s: block of %zu elements (%d x %d x %d), %zu "
			"nodes; stable step %.3g s\n", PROG, st.mesh.ne, st.mesh.nx,
			st.mesh.ny, st.mesh.nz, st.mesh.nn, dem_fe_dt(fe));
		log_effects(&st);
	}
	if ((rc = open_state(&cl, &st, argc, args, &w, &e)))
		goto fail;
	t = dem_wall();
	if ((rc = run(fe, &st, cl.com.quiet, w, &f, &cost, &e)))
		goto fail;
	dem_cost_time(&cost, "run", dem_wall() - t);
	rc = dem_state_writer_close(w, &e);
	w = NULL;
	if (rc)
		goto fail;
	if (cl.vtu && (rc = dem_vtu_write(cl.vtu, &st.mesh,
					  &(dem_vtu_fields_t){f.u, f.sig, f.eps, f.ep},
					  1, &e)))
		goto fail;

	dem_fe_energy_t en;
	dem_fe_stats_t fs;
	dem_fe_energy(fe, &en);
	dem_fe_stats(fe, &fs);
	if (cl.com.verbose)
		fprintf(stderr, "%s: energies at t = %.6g s (J): kinetic %.6g, "
			"internal %.6g (plastic %.6g), hourglass %.6g, damping "
			"%.6g, external %.6g; balance %.3g\n", PROG, en.t,
			en.kinetic, en.internal, en.plastic, en.hourglass,
			en.damping, en.external, en.balance);
	dem_cost_time(&cost, "element_loop", fs.elem_s);
	dem_cost_time(&cost, "node_loop", fs.node_s);
	dem_cost_count(&cost, "steps", (double)fs.steps);
	dem_cost_count(&cost, "elements", (double)st.mesh.ne);
	dem_cost_count(&cost, "elem_cycles", fs.elem_cycles);
	dem_cost_count(&cost, "ns_per_elem_cycle",
		       fs.elem_cycles > 0 ? 1e9 * (fs.elem_s + fs.node_s) / fs.elem_cycles : 0);
	dem_cost_count(&cost, "energy_error", en.scale > 0 ? fabs(en.balance) / en.scale : 0);
done:
	fields_free(&f);
	dem_fe_free(fe);
	settings_free(&st);
	dem_scene_free(scene);
	free(args);
	dem_common_free(&cl.com);
	if (!cl.com.output && (rc = dem_cli_close_stdout(PROG)))
		return rc;
	if (!cl.com.dump)
		dem_cost_print(&cost, PROG, stderr);
	return 0;
fail:
	fprintf(stderr, "%s: %s\n", PROG, e.msg);
	if (rc == DEM_EUSAGE)
		fprintf(stderr, "Try '%s --help' for more information.\n", PROG);
	dem_state_writer_abort(w);
	fields_free(&f);
	dem_fe_free(fe);
	settings_free(&st);
	dem_scene_free(scene);
	free(args);
	dem_common_free(&cl.com);
	return rc;
}
