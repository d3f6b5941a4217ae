/* demform - the implicit forming stage of peen forming (Ch. 8.5).
 *
 *   demform [OPTION]... [FILE]
 *
 * Reads residual profiles (a profile stream, FILE or standard input),
 * applies them as initial stresses (or strains) with their effective
 * plastic strain to a plate of hexahedra built from the scene, finds the
 * equilibrium by Newton-Raphson (small or large strain, pseudo-load
 * increments with cut-back), and prints the formed shape: arc height,
 * the Almen gauge's reading (SAE J442), curvatures, the stress through the
 * thickness at the centre, the Newton log.  See demform(1).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif
#include "core/afile.h"
#include "core/cli.h"
#include "core/cost.h"
#include "fe/fescene.h"
#include "fe/implicit.h"
#include "io/profile.h"
#include "io/scene.h"
#include "io/vtu.h"

#define PROG "demform"
#define MAXSTEP 9

enum { OPT_LARGE = DEM_OPT_PROGRAM, OPT_INCREMENTS, OPT_INIT, OPT_CENTRE, OPT_PASS, OPT_VTU, OPT_THREADS };

static const dem_opt_t options[] = {
	{"large", OPT_LARGE, NULL, "large strain (geometric nonlinearity; sets form.strain: large)"},
	{"increments", OPT_INCREMENTS, "N", "initial load increments of each step (form.increments, default 1)"},
	{"init", OPT_INIT, "WHAT", "initial condition: stress (default) or strain (form.init)"},
	{"pass", OPT_PASS, "N", "use pass N of the profile stream (form.pass; default the last)"},
	{"centre", OPT_CENTRE, "FILE", "write the stress through the thickness at the plate centre to FILE"},
	{"vtu", OPT_VTU, "FILE", "write the formed plate (displacements, element stresses) as VTK XML to FILE"},
	{"threads", OPT_THREADS, "N", "threads of the assembly and of an OpenBLAS factorisation (default: OMP_NUM_THREADS or all)"},
	DEM_OPTS_COMMON,
	{0}
};

static const char usage[] = "Usage: demform [OPTION]... [FILE]\n";
static const char purpose[] =
	"Form a plate with residual profiles (a profile stream, FILE or standard input)\n"
	"as initial conditions (Ch. 8.5): implicit static Newton-Raphson, then print\n"
	"the arc height, the Almen gauge's reading, curvatures and Newton log as\n"
	"'key: value' lines.\n";
static const char epilogue[] =
	"Examples:\n"
	"  demprofile state.gz | demform -s strip.yaml\n"
	"  demform -s strip.yaml --large --centre centre.txt profile.txt\n"
	"\nSee demform(1), dem-scene(5) and dem-streams(5).\n";

struct cmdline {
	dem_common_t com;
	const char *input;
	const char *centre;
	const char *vtu;
	unsigned long threads;
};

static int parse_cmdline(int argc, char **argv, struct cmdline *cl)
{
	dem_cli_t c;
	dem_common_t *m = &cl->com;
	int k;

	memset(cl, 0, sizeof *cl);
	if (dem_common_init(m, argc) || dem_cli_init(&c, PROG, options, usage, purpose, epilogue))
		return DEM_EIO;
	while ((k = dem_cli_option(&c, m, argc, argv)) != -1) {
		switch (k) {
		case OPT_LARGE: dem_common_override(m, "form.strain", "large", "--large"); break;
		case OPT_INCREMENTS: dem_common_override(m, "form.increments", optarg, "--increments"); break;
		case OPT_INIT: dem_common_override(m, "form.init", optarg, "--init"); break;
		case OPT_PASS: dem_common_override(m, "form.pass", optarg, "--pass"); break;
		case OPT_CENTRE: cl->centre = optarg; break;
		case OPT_VTU: cl->vtu = optarg; break;
		case OPT_THREADS: dem_cli_ulong(&c, "--threads", optarg, 1, 1024, &cl->threads); break;
		default: break;
		}
	}
	if (c.done < 0) {
		cl->input = dem_cli_operand(&c, argc, argv, "input");
		if (m->binary || m->gzip)
			dem_cli_error(&c, "the summary is text: -b and -z do not apply");
	}
	return dem_cli_done(&c);
}

/* One profile of a step: where it goes and where it comes from. */
struct app {
	const char *file;       /* "-": the input */
	long pass;              /* -1: the last */
	double scale;
	dem_form_region_t r;
};

struct step {
	int napp;
	struct app app[2];      /* top, bottom */
	dem_bc_t bc[6];
	int minimal;
};

struct settings {
	dem_plate_t plate;
	dem_form_opts_t opts;
	int init;
	double chord, fit[2];
	int chord_axis;
	double gauge[2];        /* the gauge's ball rectangle, lx x ly */
	int gauge_fits;         /* on the plate: a reading per step */
	long pass;
	int plane;              /* form.plane_strain: 0 auto, 1 false, 2 true */
	int nstep;
	struct step step[MAXSTEP];
};

static int read_app(dem_scene_t *s, const char *base, int bottom, long pass, struct app *a,
		    dem_error_t *e)
{
	char key[160];
	double reg[4];
	snprintf(key, sizeof key, "%s.file", base);
	if (dem_scene_string(s, key, "-", &a->file, e))
		return e->code;
	snprintf(key, sizeof key, "%s.pass", base);
	if (dem_scene_int(s, key, pass, -1, 1000000, &a->pass, e))
		return e->code;
	snprintf(key, sizeof key, "%s.scale", base);
	if (dem_scene_quantity(s, key, DEM_DIM_NONE, 1, -1e6, 1e6, &a->scale, e))
		return e->code;
	snprintf(key, sizeof key, "%s.region", base);
	a->r.bottom = bottom;
	a->r.x0 = a->r.y0 = -HUGE_VAL;
	a->r.x1 = a->r.y1 = HUGE_VAL;
	if (dem_scene_has(s, key)) {
		if (dem_scene_vector(s, key, DEM_DIM_LENGTH, 4, NULL, -HUGE_VAL, HUGE_VAL, reg, e))
			return e->code;
		if (!(reg[0] < reg[1] && reg[2] < reg[3]))
			return dem_scene_error(s, key, e, "expected [x0, x1, y0, y1] with x0 < x1 "
					       "and y0 < y1");
		a->r.x0 = reg[0], a->r.x1 = reg[1], a->r.y0 = reg[2], a->r.y1 = reg[3];
	}
	return DEM_OK;
}

static int read_scene(dem_scene_t *s, int accuracy, struct settings *st, dem_error_t *e)
{
	static const char *const sections[] = {"plate", "form", "material", NULL};
	static const char *const strains[] = {"small", "large", NULL};
	static const char *const elems[] = {"full", "bbar", "eas", NULL};
	static const char *const inits[] = {"stress", "strain", NULL};
	static const char *const axes[] = {"x", "y", NULL};
	static const char *const planes[] = {"auto", "false", "true", NULL};
	static const char *const bcs[] = {"free", "fixed", "normal", NULL};
	static const char *const faces[] = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
	static const double size0[3] = {0.150, 0.050, 0.004}, fit0[2] = {1, 1};
	/* The J442 gauge's balls: 1.25 x 0.625 in (31.75 x 15.875 mm), a
	 * labelled default, not read from the standard (demform(1)). */
	static const double gauge0[2] = {0.03175, 0.015875};
	static const double tol0[3] = {1e-6, 1e-8, 1e-10};  /* --accuracy */
	double size[3];
	long nz, it, ninc, cuts;
	int large, rule, two;

	dem_plate_t *p = &st->plate;
	if (dem_scene_vector(s, "plate.size", DEM_DIM_LENGTH, 3, size0, DEM_SCENE_GT0, HUGE_VAL, size, e) ||
	    dem_scene_quantity(s, "plate.element", DEM_DIM_LENGTH, 0.005, DEM_SCENE_GT0, HUGE_VAL, &p->dxy, e) ||
	    dem_scene_int(s, "plate.layers", 15, 1, 10000, &nz, e) ||
	    dem_scene_quantity(s, "plate.grading", DEM_DIM_NONE, 1.2, 1, 10, &p->grade, e) ||
	    dem_scene_bool(s, "plate.two_sided", 0, &two, e))
		return e->code;
	p->L = size[0], p->W = size[1], p->h = size[2];
	p->nz = (int)nz;
	p->two_sided = two;

	dem_form_opts_t *o = &st->opts;
	dem_form_opts_default(o);
	if (dem_scene_choice(s, "form.strain", strains, 0, &large, e) ||
	    dem_scene_choice(s, "form.element", elems, DEM_HEX8_EAS, &rule, e) ||
	    dem_scene_choice(s, "form.init", inits, 0, &st->init, e) ||
	    dem_scene_quantity(s, "form.tolerance", DEM_DIM_NONE, tol0[accuracy], 1e-15, 1e-2, &o->tol, e) ||
	    dem_scene_int(s, "form.iterations", 12, 1, 1000, &it, e) ||
	    dem_scene_int(s, "form.increments", 1, 1, 1000000, &ninc, e) ||
	    dem_scene_int(s, "form.cutbacks", 10, 0, 50, &cuts, e) ||
	    dem_scene_quantity(s, "form.chord", DEM_DIM_LENGTH, p->L, DEM_SCENE_GT0, HUGE_VAL, &st->chord, e) ||
	    dem_scene_choice(s, "form.chord_axis", axes, 0, &st->chord_axis, e) ||
	    dem_scene_vector(s, "form.fit", DEM_DIM_NONE, 2, fit0, DEM_SCENE_GT0, 1, st->fit, e) ||
	    dem_scene_vector(s, "form.gauge", DEM_DIM_LENGTH, 2, gauge0, DEM_SCENE_GT0, HUGE_VAL, st->gauge, e) ||
	    dem_scene_int(s, "form.pass", -1, -1, 1000000, &st->pass, e) ||
	    dem_scene_choice(s, "form.plane_strain", planes, 0, &st->plane, e))
		return e->code;
	o->large = large;
	o->rule = (dem_hex8_rule_t)rule;
	o->maxit = (int)it;
	o->ninc = (int)ninc;
	o->maxcut = (int)cuts;
	if (large && rule == DEM_HEX8_BBAR)
		return dem_scene_error(s, "form.element", e, "bbar is small strain only");
	if (st->chord > (st->chord_axis ? p->W : p->L) * (1 + 1e-12))
		return dem_scene_error(s, "form.chord", e, "longer than the plate");
	/* on a plate smaller than the default rectangle, no reading; one the
	 * scene gives must fit */
	st->gauge_fits = st->gauge[0] <= p->L * (1 + 1e-12) && st->gauge[1] <= p->W * (1 + 1e-12);
	if (!st->gauge_fits && dem_scene_has(s, "form.gauge"))
		return dem_scene_error(s, "form.gauge", e, "the balls' rectangle %g x %g m is larger "
				       "than the plate (%g x %g m)", st->gauge[0], st->gauge[1], p->L, p->W);

	st->nstep = 0;
	for (int k = 1; k <= MAXSTEP; k++) {
		char base[32], key[64];
		snprintf(base, sizeof base, "form.step%d", k);
		if (!dem_scene_has(s, base))
			break;
		struct step *sp = &st->step[st->nstep++];
		memset(sp, 0, sizeof *sp);
		for (int b = 0; b < 2; b++) {
			snprintf(key, sizeof key, "%s.%s", base, b ? "bottom" : "top");
			if (dem_scene_has(s, key) && read_app(s, key, b, st->pass, &sp->app[sp->napp++], e))
				return e->code;
		}
		int any = 0;
		for (int f = 0; f < 6; f++) {
			int c;
			snprintf(key, sizeof key, "%s.bc.%s", base, faces[f]);
			if (dem_scene_choice(s, key, bcs, 0, &c, e))
				return e->code;
			sp->bc[f] = (dem_bc_t)c;
			any |= c != 0;
		}
		snprintf(key, sizeof key, "%s.minimal", base);
		if (dem_scene_bool(s, key, !any, &sp->minimal, e))
			return e->code;
	}
	if (st->nstep == 0) {   /* the default job: the input on the whole top face */
		struct step *sp = &st->step[st->nstep++];
		memset(sp, 0, sizeof *sp);
		sp->napp = 1;
		sp->minimal = 1;
		struct app *a = &sp->app[0];
		a->file = "-";
		a->pass = st->pass;
		a->scale = 1;
		a->r.x0 = a->r.y0 = -HUGE_VAL;
		a->r.x1 = a->r.y1 = HUGE_VAL;
	}
	return dem_scene_check(s, sections, e);
}

/* The input stream is read once (it may be standard input); steps may name
 * other files. */
struct inputs {
	dem_profile_t *in;
	int nin;
};

static int get_profile(struct inputs *ip, const char *input, const struct app *a,
		       dem_profile_t *own, const dem_profile_t **out, dem_error_t *e)
{
	int rc;
	if (strcmp(a->file, "-") == 0) {
		if (!ip->in && (rc = dem_profile_read_all(input, &ip->in, &ip->nin, e)))
			return rc;
		if (ip->nin < 1)
			return dem_error_set(e, DEM_EINPUT, "%s: no profile in the stream",
					     input ? input : "stdin");
		if (a->pass < 0) {
			*out = &ip->in[ip->nin - 1];
			return DEM_OK;
		}
		for (int k = 0; k < ip->nin; k++)
			if (ip->in[k].pass == a->pass) {
				*out = &ip->in[k];
				return DEM_OK;
			}
		return dem_error_set(e, DEM_EINPUT, "%s: no pass %ld in the profile stream",
				     input ? input : "stdin", a->pass);
	}
	if ((rc = dem_profile_read(a->file, (int)a->pass, own, e)))
		return rc;
	*out = own;
	return DEM_OK;
}

struct logctx {
	FILE *sum;              /* the summary (Newton log lines) */
	int verbose;
};

static void newton_log(void *ctx, int step, int inc, double lambda, int iter, double rn,
		       double rrel, double dun)
{
	struct logctx *c = ctx;
	fprintf(c->sum, "newton: %d %d %.6g %d %.6e %.6e %.6e\n", step, inc, lambda, iter, rn,
		rrel, dun);
	if (c->verbose)
		fprintf(stderr, "%s: step %d increment %d lambda %.4g iteration %d |R| %.3e N "
			"(%.3e) |du| %.3e m\n", PROG, step, inc, lambda, iter, rn, rrel, dun);
}

/* Write text to path atomically (temporary name, then rename), or to
 * standard output when path is NULL. */
static int write_text(const char *path, const char *text, size_t len, dem_error_t *e)
{
	dem_afile_t a;
	int rc;

	if (!path) {
		fwrite(text, 1, len, stdout);
		return DEM_OK;
	}
	if ((rc = dem_afile_open(&a, path, "w", e)))
		return rc;
	fwrite(text, 1, len, a.f);
	return dem_afile_commit(&a, 0, e);
}

/* The plate for ParaView: displacements and the element means of the
 * Gauss point stresses and effective plastic strains. */
static int write_vtu(const char *path, const dem_form_t *f, const dem_mesh_t *m,
		     dem_error_t *e)
{
	double *sig = malloc(6 * m->ne * sizeof *sig), *ep = malloc(m->ne * sizeof *ep);
	if (!sig || !ep) {
		free(sig), free(ep);
		return dem_error_nomem(e, "VTU fields");
	}
	const dem_hex8_hist_t *h = dem_form_hist(f);
	for (size_t el = 0; el < m->ne; el++) {
		ep[el] = 0;
		for (int k = 0; k < 6; k++)
			sig[6 * el + k] = 0;
		for (int p = 0; p < 8; p++) {
			ep[el] += h[el].ep[p] / 8;
			for (int k = 0; k < 6; k++)
				sig[6 * el + k] += h[el].sig[6 * p + k] / 8;
		}
	}
	dem_vtu_fields_t fl = {dem_form_disp(f), sig, NULL, ep};
	int rc = dem_vtu_write(path, m, &fl, 1, e);
	free(sig), free(ep);
	return rc;
}

static int write_centre(const char *path, const dem_form_t *f, int nz, dem_error_t *e)
{
	int n;
	size_t m = 2 * (size_t)nz;
	double *d = malloc(m * sizeof *d), *s = malloc(6 * m * sizeof *s), *ep = malloc(m * sizeof *ep);
	char *buf = NULL;
	size_t len = 0;
	FILE *mf = NULL;
	int rc = DEM_OK;
	if (!d || !s || !ep || !(mf = open_memstream(&buf, &len))) {
		rc = dem_error_nomem(e, "centre profile");
		goto out;
	}
	dem_form_centre_profile(f, &n, d, s, ep);
	fprintf(mf, "# demform centre profile: stress through the thickness at the plate centre\n"
		"# depth:m sxx:Pa syy:Pa szz:Pa sxy:Pa syz:Pa szx:Pa ep:-\n");
	for (int i = 0; i < n; i++)
		fprintf(mf, "%.9g %.9g %.9g %.9g %.9g %.9g %.9g %.9g\n", d[i], s[6 * i], s[6 * i + 1],
			s[6 * i + 2], s[6 * i + 3], s[6 * i + 4], s[6 * i + 5], ep[i]);
	fprintf(mf, "# end %d\n", n);
	fclose(mf);
	mf = NULL;
	rc = write_text(path, buf, len, e);
out:
	free(buf), free(d), free(s), free(ep);
	return rc;
}

/* A run: the scene (the settings name its files), the strip, its
 * forming and the summary it writes. */
struct job {
	dem_scene_t *scene;
	struct settings set;
	dem_mat_t mat;
	dem_mesh_t mesh;
	dem_form_t *form;
	struct inputs ip;
	dem_form_stats_t st;
	char *sbuf;             /* the summary */
	size_t slen;
};

static void job_free(struct job *j)
{
	free(j->sbuf);
	for (int k = 0; k < j->ip.nin; k++)
		dem_profile_free(&j->ip.in[k]);
	free(j->ip.in);
	dem_form_free(j->form);
	dem_mesh_free(&j->mesh);
	dem_mat_free(&j->mat);
	dem_scene_free(j->scene);
}

/* The scene's material and settings with the options' overrides;
 * --dump-scene prints them. */
static int get_settings(const struct cmdline *cl, struct job *j, dem_error_t *e)
{
	int rc;

	if ((rc = dem_scene_open(&j->scene, &cl->com, e)) ||
	    (rc = dem_scene_material(j->scene, 0, &j->mat, e)) ||
	    (rc = read_scene(j->scene, cl->com.accuracy, &j->set, e)))
		return rc;
	if (cl->com.dump)
		dem_scene_dump(j->scene, stdout);
	return DEM_OK;
}

/* The strip's mesh and its implicit model. */
static int build(const struct cmdline *cl, struct job *j, dem_cost_t *cost, dem_error_t *e)
{
	double t = dem_wall();
	int rc;

	if (j->mat.flags & DEM_MAT_KIN) {
		/* the profile carries no back-stresses: the strip's material
		 * is the law's monotonic curve (demform(1)) */
		dem_mat_kin_as_iso(&j->mat);
		if (!cl->com.quiet)
			fprintf(stderr, "demform: kinematic hardening read as its monotonic "
				"curve (the profile has no back-stresses)\n");
	}
	if ((rc = dem_plate_mesh(&j->set.plate, &j->mesh, e)) ||
	    (rc = dem_form_create(&j->form, &j->mesh, &j->mat, e)))
		return rc;
	dem_cost_time(cost, "mesh", dem_wall() - t);
	return DEM_OK;
}

/* One step: its profiles applied, the equilibrium found, the shape
 * measured into the summary. */
static int form_step(const struct cmdline *cl, struct job *j, int k, FILE *sum,
		     dem_cost_t *cost, dem_error_t *e)
{
	const struct settings *set = &j->set;
	const struct step *sp = &set->step[k];
	double t = dem_wall();
	int rc;

	int nplane = 0;
	for (int a = 0; a < sp->napp; a++) {
		dem_profile_t own = {0};
		const dem_profile_t *p = NULL;
		rc = get_profile(&j->ip, cl->input, &sp->app[a], &own, &p, e);
		if (!rc) {
			nplane += p->plane;
			rc = dem_form_profile(j->form, p, &sp->app[a].r,
					      set->init ? DEM_FORM_STRAIN : DEM_FORM_SIGMA,
					      sp->app[a].scale, e);
		}
		dem_profile_free(&own);
		if (rc)
			return rc;
	}
	dem_cost_time(cost, "profile", dem_wall() - t);
	/* form.plane_strain auto: a 2D plane-strain block's profiles form a
	 * plane-strain strip (demform(1)); mixed with others, the scene
	 * must say */
	if (set->plane == 0 && nplane > 0 && nplane < sp->napp)
		return dem_error_set(e, DEM_EINPUT, "step %d: profiles of a 2D plane-strain block "
				     "and of a 3D one: set form.plane_strain (true or false)", k + 1);
	int plane = set->plane == 2 || (set->plane == 0 && sp->napp > 0 && nplane == sp->napp);
	dem_form_constrain(j->form, sp->bc, sp->minimal);
	if (plane) {
		dem_form_plane_strain(j->form);
		if (!cl->com.quiet)
			fprintf(stderr, "%s: step %d: plane strain along y%s: u_y held at every "
				"node, the profile's syy the constraint's\n", PROG, k + 1,
				set->plane == 2 ? "" : " (the profile is of a 2D plane-strain block)");
	}
	if ((rc = dem_form_step(j->form, &set->opts, &j->st, e)))
		return rc;
	dem_form_shape_t sh;
	if ((rc = dem_form_shape(j->form, set->chord, set->chord_axis, set->fit[0], set->fit[1],
				 &sh, e)))
		return rc;
	fprintf(sum, "step: %d\nplane_strain: %s\narc_height: %.9g\nchord: %.9g\n", k + 1,
		plane ? "true" : "false", sh.arc, set->chord);
	if (set->gauge_fits) {
		double gh;
		if ((rc = dem_form_gauge(j->form, set->gauge[0], set->gauge[1], &gh, e)))
			return rc;
		fprintf(sum, "gauge_height: %.9g\n", gh);
	}
	fprintf(sum, "max_deflection: %.9g\n"
		"curvature_x: %.9g\ncurvature_y: %.9g\ncurvature_xy: %.9g\n"
		"residual: %.6e\nresidual_rel: %.6e\nload: %.6e\n",
		sh.wmax, sh.kx, sh.ky, sh.kxy, j->st.rnorm, j->st.rrel, j->st.fnorm);
	if (!cl->com.quiet && cl->com.verbose)
		fprintf(stderr, "%s: step %d: arc height %.6g m, curvatures %.6g %.6g 1/m\n",
			PROG, k + 1, sh.arc, sh.kx, sh.ky);
	return DEM_OK;
}

/* Every step, the summary kept in memory until all have converged. */
static int form_steps(const struct cmdline *cl, struct job *j, dem_cost_t *cost, dem_error_t *e)
{
	struct settings *set = &j->set;
	FILE *sum = open_memstream(&j->sbuf, &j->slen);
	int rc = DEM_OK;

	if (!sum)
		return dem_error_nomem(e, "summary");
	struct logctx lc = {sum, cl->com.verbose && !cl->com.quiet};
	set->opts.log = newton_log;
	set->opts.ctx = &lc;
	fprintf(sum, "# demform %s summary; lengths in m, curvatures in 1/m, stresses in Pa\n",
		DEM_VERSION);
	fprintf(sum, "plate: %g %g %g\nelements: %zu\nnodes: %zu\nstrain: %s\nelement: %s\n",
		set->plate.L, set->plate.W, set->plate.h, j->mesh.ne, j->mesh.nn,
		set->opts.large ? "large" : "small",
		set->opts.rule == DEM_HEX8_EAS ? "eas" : set->opts.rule == DEM_HEX8_BBAR ? "bbar" : "full");
	if (set->gauge_fits)
		fprintf(sum, "gauge: %.9g %.9g\n", set->gauge[0], set->gauge[1]);
	fprintf(sum, "# newton: step increment lambda iteration |R|:N |R|/|F| |du|:m\n");
	for (int k = 0; k < set->nstep && !rc; k++)
		rc = form_step(cl, j, k, sum, cost, e);
	if (!rc)
		fprintf(sum, "increments: %d\ncutbacks: %d\niterations: %d\nfactorisations: %d\n",
			j->st.increments, j->st.cutbacks, j->st.iterations, j->st.factorisations);
	fclose(sum);
	set->opts.ctx = NULL;
	return rc;
}

static int write_outputs(const struct cmdline *cl, const struct job *j, dem_error_t *e)
{
	int rc;

	if ((cl->centre && (rc = write_centre(cl->centre, j->form, j->mesh.nz, e))) ||
	    (cl->vtu && (rc = write_vtu(cl->vtu, j->form, &j->mesh, e))))
		return rc;
	return write_text(cl->com.output, j->sbuf, j->slen, e);
}

static void report(const struct job *j, int blas, dem_cost_t *cost)
{
	const dem_form_stats_t *st = &j->st;

	dem_cost_time(cost, "assemble", st->assemble_s);
	dem_cost_time(cost, "factor", st->factor_s);
	dem_cost_time(cost, "solve", st->solve_s);
	dem_cost_count(cost, "elements", (double)j->mesh.ne);
	dem_cost_count(cost, "equations", (double)st->neq);
	dem_cost_count(cost, "increments", st->increments);
	dem_cost_count(cost, "cutbacks", st->cutbacks);
	dem_cost_count(cost, "iterations", st->iterations);
	dem_cost_count(cost, "factorisations", st->factorisations);
	dem_cost_count(cost, "factor_nnz", st->lnz);
#ifdef _OPENMP
	dem_cost_count(cost, "threads", omp_get_max_threads());
#endif
	dem_cost_count(cost, "blas_threads", blas);
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
	int blas = dem_form_threads((int)cl.threads);
	if (!(rc = get_settings(&cl, &j, &r.e)) && !cl.com.dump &&
	    !(rc = build(&cl, &j, &r.cost, &r.e)) &&
	    !(rc = form_steps(&cl, &j, &r.cost, &r.e)) &&
	    !(rc = write_outputs(&cl, &j, &r.e)))
		report(&j, blas, &r.cost);
	job_free(&j);
	return dem_main_end(&r, &cl.com, rc);
}
