/* demfit - the saturation point and intensity of an Almen saturation curve
 * (SAE J443), fitted in the forms of SAE J2597's solver.
 *
 *   demfit [OPTION]... [FILE]
 *
 * Reads a table of exposure and arc height (FILE or standard input, one
 * point a row, '#' lines and blank lines skipped), fits the two- and/or
 * three-parameter exponential by nonlinear least squares (the library's
 * fitter, core/saturation.h), and prints each fit's saturation point T
 * (H(2T) = 1.1 H(T)) and intensity H(T), in m and in inches, with the J443
 * rule on the points beside them, as 'key: value' lines.  The saturation
 * curve gathers one number from many forming runs (one per exposure), so
 * no single run of demform or demprofile sees it: this filter reads the
 * table the reports build.  See demfit(1).
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/afile.h"
#include "core/cli.h"
#include "core/cost.h"
#include "core/saturation.h"
#include "core/units.h"

#define PROG "demfit"
#define INCH 0.0254

enum { OPT_FORM = DEM_OPT_PROGRAM, OPT_COLUMNS, OPT_UNIT, OPT_STRIP };

static const dem_opt_t options[] = {
	{"form", OPT_FORM, "FORM", "the curve: exp2, exp3 or both (default both)"},
	{"columns", OPT_COLUMNS, "X:Y", "columns of the exposure and the arc height (default 1:2)"},
	{"unit", OPT_UNIT, "UNIT", "unit of the arc heights: m (default), mm, um"},
	{"strip", OPT_STRIP, "S", "the Almen strip, A, N or C, for the designation (default A)"},
	DEM_OPTS_COMMON,
	{0}
};

static const char usage[] = "Usage: demfit [OPTION]... [FILE]\n";
static const char purpose[] =
	"Fit an Almen saturation curve (rows of exposure and arc height, FILE or\n"
	"standard input) in the forms of SAE J2597's solver and print its saturation\n"
	"point T (H(2T) = 1.1 H(T), SAE J443) and intensity H(T), with the rule on\n"
	"the points themselves, as 'key: value' lines.\n";
static const char epilogue[] =
	"Examples:\n"
	"  demfit --unit mm --columns 1:3 curve.txt\n"
	"  demfit --form exp2 -o fit.txt heights.txt\n"
	"\nSee demfit(1) and demform(1).\n";

struct cmdline {
	dem_common_t com;
	const char *input;
	int forms;              /* bit 0: exp2, bit 1: exp3 */
	unsigned long cx, cy;   /* columns, from 1 */
	double unit;            /* m per unit of the heights */
	char strip;
};

static int parse_cmdline(int argc, char **argv, struct cmdline *cl)
{
	dem_cli_t c;
	dem_common_t *m = &cl->com;
	int k;

	memset(cl, 0, sizeof *cl);
	cl->forms = 3;
	cl->cx = 1, cl->cy = 2;
	cl->unit = 1;
	cl->strip = 'A';
	if (dem_common_init(m, argc) || dem_cli_init(&c, PROG, options, usage, purpose, epilogue))
		return DEM_EIO;
	while ((k = dem_cli_option(&c, m, argc, argv)) != -1) {
		switch (k) {
		case OPT_FORM:
			if (strcmp(optarg, "exp2") == 0)
				cl->forms = 1;
			else if (strcmp(optarg, "exp3") == 0)
				cl->forms = 2;
			else if (strcmp(optarg, "both") == 0)
				cl->forms = 3;
			else
				dem_cli_error(&c, "--form '%s': expected exp2, exp3 or both", optarg);
			break;
		case OPT_COLUMNS: {
			unsigned long x, y;
			char extra;
			if (sscanf(optarg, "%lu:%lu%c", &x, &y, &extra) != 2 || x < 1 || y < 1 ||
			    x > 1000 || y > 1000 || x == y)
				dem_cli_error(&c, "--columns '%s': expected X:Y, two different "
					      "columns from 1", optarg);
			else
				cl->cx = x, cl->cy = y;
			break;
		}
		case OPT_UNIT: {
			char text[64], why[160];
			snprintf(text, sizeof text, "1 %s", optarg);
			if (strlen(optarg) > 32 ||
			    dem_units_parse(text, DEM_DIM_LENGTH, &cl->unit, why, sizeof why))
				dem_cli_error(&c, "--unit '%s': expected a length unit (m, mm, um)",
					      optarg);
			break;
		}
		case OPT_STRIP:
			if (strlen(optarg) == 1 && strchr("ANC", optarg[0]))
				cl->strip = optarg[0];
			else
				dem_cli_error(&c, "--strip '%s': expected A, N or C", optarg);
			break;
		default: break;
		}
	}
	if (c.done < 0) {
		cl->input = dem_cli_operand(&c, argc, argv, "input");
		if (m->binary || m->gzip)
			dem_cli_error(&c, "the summary is text: -b and -z do not apply");
		if (m->scene || m->dump)
			dem_cli_error(&c, "demfit reads no scene: -s and --dump-scene do not apply");
	}
	return dem_cli_done(&c);
}

/* The points of the table: exposures t, heights h in m. */
static int read_points(const struct cmdline *cl, double **t, double **h, size_t *n,
		       dem_error_t *e)
{
	const char *name = cl->input ? cl->input : "stdin";
	FILE *f = cl->input && strcmp(cl->input, "-") ? fopen(cl->input, "r") : stdin;
	if (!f)
		return dem_error_set(e, DEM_EIO, "%s: %s", name, strerror(errno));
	char *line = NULL;
	size_t cap = 0, room = 0;
	long lineno = 0;
	int rc = DEM_OK;
	*t = *h = NULL;
	*n = 0;
	while (getline(&line, &cap, f) != -1) {
		lineno++;
		char *s = line + strspn(line, " \t\r\n");
		if (*s == '#' || *s == 0)
			continue;
		double v[2] = {NAN, NAN};
		unsigned long col = 0, need = cl->cx > cl->cy ? cl->cx : cl->cy;
		char *tok, *save = NULL;
		for (tok = strtok_r(s, " \t\r\n", &save); tok && col < need;
		     tok = strtok_r(NULL, " \t\r\n", &save)) {
			col++;
			if (col != cl->cx && col != cl->cy)
				continue;
			char *end;
			double x = strtod(tok, &end);
			if (*end || !isfinite(x)) {
				rc = dem_error_set(e, DEM_EINPUT, "%s:%ld: column %lu: '%s' is not a "
						   "finite number", name, lineno, col, tok);
				goto out;
			}
			v[col == cl->cx ? 0 : 1] = x;
		}
		if (col < need) {
			rc = dem_error_set(e, DEM_EINPUT, "%s:%ld: %lu column%s, expected at least %lu",
					   name, lineno, col, col == 1 ? "" : "s", need);
			goto out;
		}
		if (*n == room) {
			room = room ? 2 * room : 16;
			double *nt = realloc(*t, room * sizeof *nt);
			if (nt)
				*t = nt;
			double *nh = nt ? realloc(*h, room * sizeof *nh) : NULL;
			if (!nt || !nh) {
				rc = dem_error_nomem(e, "points");
				goto out;
			}
			*h = nh;
		}
		(*t)[*n] = v[0];
		(*h)[*n] = v[1] * cl->unit;
		++*n;
	}
	if (ferror(f))
		rc = dem_error_set(e, DEM_EIO, "%s: read error", name);
out:
	free(line);
	if (f != stdin)
		fclose(f);
	return rc;
}

static void put_fit(FILE *o, const char *k, const dem_sat_fit_t *f, double tmax, char strip)
{
	fprintf(o, "%s_a: %.9g\n%s_b: %.9g\n%s_c: %.9g\n%s_rms: %.6g\n%s_iterations: %d\n"
		"%s_saturates: %d\n", k, f->a, k, f->b, k, f->c, k, f->rms, k, f->iterations, k,
		f->saturates);
	if (!f->saturates)
		return;
	fprintf(o, "%s_T: %.9g\n%s_H: %.9g\n%s_H_mm: %.6g\n%s_H_in: %.6g\n%s_intensity: %.4f%c\n"
		"%s_extrapolated: %d\n", k, f->T, k, f->H, k, f->H * 1e3, k, f->H / INCH, k,
		f->H / INCH, strip, k, 2 * f->T > tmax * (1 + 1e-12));
}

/* The fits of the forms asked for, and the J443 rule on the points. */
struct fits {
	dem_sat_fit_t fit[2];
	int ok[2];              /* the form's fit converged */
	int found;              /* the points saturate */
	double T, H, ratio;
};

/* A form whose fit fails to converge is reported as such when the other
 * converged; bad points fail both alike. */
static int fit_curve(const struct cmdline *cl, size_t n, const double *t, const double *h,
		     struct fits *f, dem_error_t *e)
{
	const char *name = cl->input ? cl->input : "stdin";
	dem_error_t fe[2] = {{0}, {0}};
	int nok = 0;

	memset(f, 0, sizeof *f);
	for (int k = 0; k < 2; k++) {
		if (!(cl->forms >> k & 1))
			continue;
		int frc = dem_sat_fit(n, t, h, (dem_sat_form_t)k, &f->fit[k], &fe[k]);
		if (frc && frc != DEM_ENUMERIC)
			return dem_error_set(e, frc, "%s: %s", name, fe[k].msg);
		f->ok[k] = !frc;
		nok += f->ok[k];
	}
	if (!nok)
		return dem_error_set(e, DEM_ENUMERIC, "%s: %s", name, fe[cl->forms & 1 ? 0 : 1].msg);
	for (int k = 0; k < 2; k++)
		if ((cl->forms >> k & 1) && !f->ok[k] && !cl->com.quiet)
			fprintf(stderr, "%s: %s: %s\n", PROG, name, fe[k].msg);
	f->found = dem_sat_points(n, t, h, &f->T, &f->H, &f->ratio);
	return DEM_OK;
}

/* The summary, on standard output or atomically to -o FILE. */
static int write_summary(const struct cmdline *cl, size_t n, double tmax, const struct fits *f,
			 dem_error_t *e)
{
	dem_afile_t out = {0};
	FILE *o = stdout;
	int rc;

	if (cl->com.output) {
		if ((rc = dem_afile_open(&out, cl->com.output, "w", e)))
			return rc;
		o = out.f;
	}
	fprintf(o, "# demfit %s: saturation curve, H(t) = a (1 - exp(-b t^c)); heights in m "
		"(_in: inches), exposures in the input's unit\n", DEM_VERSION);
	fprintf(o, "points: %zu\nstrip: %c\n", n, cl->strip);
	for (int k = 0; k < 2; k++) {
		if (!(cl->forms >> k & 1))
			continue;
		fprintf(o, "%s_converged: %d\n", dem_sat_form_names[k], f->ok[k]);
		if (f->ok[k])
			put_fit(o, dem_sat_form_names[k], &f->fit[k], tmax, cl->strip);
	}
	fprintf(o, "points_saturates: %d\n", f->found);
	if (f->found)
		fprintf(o, "points_T: %.9g\npoints_H: %.9g\npoints_H_mm: %.6g\npoints_H_in: %.6g\n"
			"points_intensity: %.4f%c\npoints_ratio: %.6g\n", f->T, f->H, f->H * 1e3,
			f->H / INCH, f->H / INCH, cl->strip, f->ratio);
	return out.f ? dem_afile_commit(&out, 0, e) : DEM_OK;
}

int main(int argc, char **argv)
{
	struct cmdline cl;
	struct fits f;
	dem_main_t r;
	double *t = NULL, *h = NULL, w;
	size_t n = 0;
	int rc;

	if ((rc = dem_main_start(&r, PROG, argc, argv)))
		return rc;
	if ((rc = parse_cmdline(argc, argv, &cl)) >= 0)
		return dem_main_quit(&r, &cl.com, rc);
	w = dem_wall();
	if (!(rc = read_points(&cl, &t, &h, &n, &r.e))) {
		dem_cost_time(&r.cost, "read", dem_wall() - w);
		w = dem_wall();
		rc = fit_curve(&cl, n, t, h, &f, &r.e);
	}
	if (!rc) {
		dem_cost_time(&r.cost, "fit", dem_wall() - w);
		rc = write_summary(&cl, n, t[n - 1], &f, &r.e);
	}
	if (!rc) {
		dem_cost_count(&r.cost, "points", (double)n);
		for (int k = 0; k < 2; k++)
			if (f.ok[k])
				dem_cost_count(&r.cost, k ? "iterations_exp3" : "iterations_exp2",
					       f.fit[k].iterations);
	}
	free(t);
	free(h);
	return dem_main_end(&r, &cl.com, rc);
}
