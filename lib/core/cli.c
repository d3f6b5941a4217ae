#include "core/cli.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "core/error.h"

int dem_cli_init(dem_cli_t *c, const char *prog, const dem_opt_t *opts)
{
	size_t n = 0;
	while (opts[n].name)
		n++;
	memset(c, 0, sizeof *c);
	c->prog = prog;
	c->opts = opts;
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

void dem_cli_help(const dem_cli_t *c, FILE *f, const char *usage,
		  const char *purpose, const char *epilogue)
{
	fprintf(f, "%s%s\n\nOptions:\n", usage, purpose);
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
	if (epilogue)
		fprintf(f, "\n%s", epilogue);
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
