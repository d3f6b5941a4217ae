#include "core/cli.h"

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "core/error.h"

int dem_cli_init(dem_cli_t *c, const char *prog, const dem_opt_t *opts,
		 const char *usage, const char *purpose, const char *epilogue)
{
	size_t n = 0;
	while (opts[n].name)
		n++;
	/* a reader that goes away (a closed pipe) makes the next write fail
	 * with EPIPE, an I/O error the program reports and exits on with 4
	 * (DESIGN.md), removing its temporary files; by default the signal
	 * would end it silently with 128 + SIGPIPE.  A caller that set its
	 * own disposition keeps it. */
	struct sigaction old;
	if (sigaction(SIGPIPE, NULL, &old) == 0 && old.sa_handler == SIG_DFL)
		signal(SIGPIPE, SIG_IGN);
	memset(c, 0, sizeof *c);
	c->prog = prog;
	c->opts = opts;
	c->usage = usage;
	c->purpose = purpose;
	c->epilogue = epilogue;
	c->done = -1;
	c->lopts = calloc(n + 1, sizeof *c->lopts);
	c->sopts = malloc(3 * n + 2);
	if (!c->lopts || !c->sopts) {
		dem_cli_free(c);
		return -1;
	}
	char *s = c->sopts;
	*s++ = ':';             /* report a missing argument as ':' */
	for (size_t i = 0; i < n; i++) {
		const dem_opt_t *o = &opts[i];
		int has = !o->arg ? no_argument :
			  o->arg[0] == '[' ? optional_argument : required_argument;
		c->lopts[i] = (struct option){o->name, has, NULL, o->key};
		if (o->key < 256) {
			*s++ = (char)o->key;
			if (has != no_argument)
				*s++ = ':';
			if (has == optional_argument)
				*s++ = ':';
		}
	}
	*s = '\0';
	return 0;
}

void dem_cli_free(dem_cli_t *c)
{
	free(c->lopts);
	free(c->sopts);
	c->lopts = NULL;
	c->sopts = NULL;
}

void dem_cli_error(dem_cli_t *c, const char *fmt, ...)
{
	va_list ap;
	fprintf(stderr, "%s: ", c->prog);
	va_start(ap, fmt);
	vfprintf(stderr, fmt, ap);
	va_end(ap);
	fputc('\n', stderr);
	c->nerr++;
}

int dem_cli_next(dem_cli_t *c, int argc, char **argv)
{
	opterr = 0;
	int k = getopt_long(argc, argv, c->sopts, c->lopts, NULL);
	if (k == '?' || k == ':') {
		/* the offending word is the last one getopt consumed (it may have
		 * moved the operands behind it) */
		const char *arg = optind > 0 && optind <= argc ? argv[optind - 1] : "?";
		if (k == ':')
			dem_cli_error(c, "option '%s' needs an argument", arg);
		else if (optopt && optopt < 256)
			dem_cli_error(c, "unknown option '-%c'", optopt);
		else
			dem_cli_error(c, "unknown option '%s'", arg);
		return '?';
	}
	return k;
}

int dem_cli_double(dem_cli_t *c, const char *opt, const char *text,
		   double min, double max, double *out)
{
	char *end;
	errno = 0;
	double v = strtod(text, &end);
	if (end == text || *end || errno == ERANGE || !isfinite(v)) {
		dem_cli_error(c, "%s: '%s' is not a number", opt, text);
		return -1;
	}
	if (v < min || v > max) {
		if (max == HUGE_VAL)
			dem_cli_error(c, "%s: %s is out of range, expected at least %g", opt, text, min);
		else
			dem_cli_error(c, "%s: %s is out of range, expected [%g, %g]", opt, text, min, max);
		return -1;
	}
	*out = v;
	return 0;
}

int dem_cli_ulong(dem_cli_t *c, const char *opt, const char *text,
		  unsigned long min, unsigned long max, unsigned long *out)
{
	char *end;
	errno = 0;
	unsigned long v = strtoul(text, &end, 10);
	if (end == text || *end || errno == ERANGE || text[0] == '-') {
		dem_cli_error(c, "%s: '%s' is not a non-negative integer", opt, text);
		return -1;
	}
	if (v < min || v > max) {
		dem_cli_error(c, "%s: %s is out of range, expected %lu to %lu", opt, text, min, max);
		return -1;
	}
	*out = v;
	return 0;
}

void dem_cli_help(const dem_cli_t *c, FILE *f)
{
	fprintf(f, "%s%s\n\nOptions:\n", c->usage, c->purpose);
	for (const dem_opt_t *o = c->opts; o->name; o++) {
		char left[64];
		int n = 0;
		if (o->key < 256)
			n = snprintf(left, sizeof left, "  -%c, --%s", o->key, o->name);
		else
			n = snprintf(left, sizeof left, "      --%s", o->name);
		if (o->arg && n > 0 && (size_t)n < sizeof left)
			snprintf(left + n, sizeof left - (size_t)n, o->arg[0] == '[' ? "%s" : " %s", o->arg);
		fprintf(f, "%-28s %s\n", left, o->help);
	}
	if (c->epilogue)
		fprintf(f, "\n%s", c->epilogue);
}

int dem_common_init(dem_common_t *m, int argc)
{
	memset(m, 0, sizeof *m);
	m->accuracy = DEM_ACCURACY_NORMAL;
	/* an argument sets at most two keys (e.g. --shape TOL), plus the verb */
	m->cap = 2 * argc + 2;
	m->ov = malloc((size_t)m->cap * sizeof *m->ov);
	m->owned = malloc((size_t)m->cap * sizeof *m->owned);
	return m->ov && m->owned ? 0 : -1;
}

void dem_common_free(dem_common_t *m)
{
	for (int i = 0; i < m->nowned; i++)
		free(m->owned[i]);
	free(m->owned);
	free(m->ov);
	m->owned = NULL;
	m->ov = NULL;
	m->nowned = m->nov = m->cap = 0;
}

void dem_common_override(dem_common_t *m, const char *key, const char *text,
			 const char *origin)
{
	if (m->nov < m->cap)
		m->ov[m->nov++] = (dem_override_t){key, text, origin};
}

int dem_common_override_vector(dem_common_t *m, const char *key,
			       const char *text, const char *origin)
{
	char *t = strdup(text);
	if (!t || m->nowned == m->cap) {
		free(t);
		return -1;
	}
	m->owned[m->nowned++] = t;
	for (char *p = t; *p; p++)
		if (*p == ':')
			*p = ',';
	dem_common_override(m, key, t, origin);
	return 0;
}

int dem_cli_common(dem_cli_t *c, int key, const char *arg, dem_common_t *m)
{
	static const char *const levels[] = {"coarse", "normal", "fine"};

	switch (key) {
	case 's': m->scene = arg; break;
	case 'o': m->output = arg; break;
	case 'b': m->binary = 1; break;
	case 'z': m->gzip = 1; break;
	case 'v': m->verbose++; break;
	case 'q': m->quiet = 1; break;
	case DEM_OPT_DUMP_SCENE: m->dump = 1; break;
	case DEM_OPT_SEED:
		if (dem_cli_ulong(c, "--seed", arg, 0, 0xffffffffUL, &m->seed) == 0)
			m->have_seed = 1;
		break;
	case DEM_OPT_ACCURACY:
		for (m->accuracy = 2; m->accuracy >= 0; m->accuracy--)
			if (strcmp(arg, levels[m->accuracy]) == 0)
				break;
		if (m->accuracy < 0) {
			dem_cli_error(c, "--accuracy: '%s': expected coarse, normal or fine", arg);
			m->accuracy = DEM_ACCURACY_NORMAL;
		}
		break;
	case 'h':
		dem_cli_help(c, stdout);
		c->done = 0;
		break;
	case DEM_OPT_VERSION:
		dem_cli_version(c);
		c->done = 0;
		break;
	default:
		return 0;
	}
	return 1;
}

int dem_cli_option(dem_cli_t *c, dem_common_t *m, int argc, char **argv)
{
	int k;

	while ((k = dem_cli_next(c, argc, argv)) != -1 && dem_cli_common(c, k, optarg, m))
		;
	return k;
}

const char *dem_cli_operand(dem_cli_t *c, int argc, char **argv, const char *what)
{
	const char *arg = optind < argc ? argv[optind++] : NULL;

	if (optind < argc)
		dem_cli_error(c, "unexpected argument '%s' (one %s at most)", argv[optind], what);
	return arg;
}

int dem_cli_done(dem_cli_t *c)
{
	int done = c->done;

	if (done < 0 && dem_cli_finish(c))
		done = DEM_EUSAGE;
	dem_cli_free(c);
	return done;
}

int dem_cli_finish(const dem_cli_t *c)
{
	if (!c->nerr)
		return 0;
	fprintf(stderr, "Try '%s --help' for more information.\n", c->prog);
	return DEM_EUSAGE;
}

void dem_cli_version(const dem_cli_t *c)
{
	printf("%s (dem toolkit) %s\n", c->prog, DEM_VERSION);
}

int dem_cli_close_stdout(const char *prog)
{
	if (fflush(stdout) != 0 || ferror(stdout) || fclose(stdout) != 0) {
		fprintf(stderr, "%s: standard output: %s\n", prog, strerror(errno ? errno : EIO));
		return DEM_EIO;
	}
	return 0;
}

int dem_cli_end(const char *prog, const dem_common_t *m, const dem_cost_t *cost)
{
	int rc;

	/* --dump-scene writes stdout whatever -o says */
	if ((!m->output || m->dump) && (rc = dem_cli_close_stdout(prog)))
		return rc;
	if (!m->dump)
		dem_cost_print(cost, prog, stderr);
	return 0;
}

int dem_cli_fail(const char *prog, int rc, const dem_error_t *e)
{
	fprintf(stderr, "%s: %s\n", prog, e->msg);
	if (rc == DEM_EUSAGE)
		fprintf(stderr, "Try '%s --help' for more information.\n", prog);
	return rc;
}

int dem_main_start(dem_main_t *r, const char *prog, int argc, char **argv)
{
	memset(r, 0, sizeof *r);
	r->prog = prog;
	dem_cost_start(&r->cost);
	gsl_set_error_handler_off();
	r->argc = argc;
	r->args = malloc(((size_t)argc + 1) * sizeof *r->args);
	if (!r->args)
		return DEM_EIO;
	memcpy(r->args, argv, ((size_t)argc + 1) * sizeof *r->args);
	return DEM_OK;
}

int dem_main_quit(dem_main_t *r, dem_common_t *m, int rc)
{
	free(r->args);
	r->args = NULL;
	dem_common_free(m);
	return rc;
}

int dem_main_end(dem_main_t *r, dem_common_t *m, int rc)
{
	if (rc)
		dem_cli_fail(r->prog, rc, &r->e);
	free(r->args);
	r->args = NULL;
	if (!rc)
		rc = dem_cli_end(r->prog, m, &r->cost);
	dem_common_free(m);
	return rc;
}
