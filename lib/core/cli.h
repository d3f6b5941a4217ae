/* cli.h - one option table per program drives parsing and --help.
 *
 * A program lists its options in a dem_opt_t table ending with
 * DEM_OPTS_COMMON (the options every program shares, DESIGN.md) and
 * {0}.  dem_cli_next() wraps getopt_long; errors are counted, each printed
 * once as "prog: message", so a program can report every mistake and exit
 * once with DEM_EUSAGE and "Try 'prog --help'".
 */
#ifndef DEM_CORE_CLI_H
#define DEM_CORE_CLI_H

#include <getopt.h>
#include <stdio.h>

#include "core/cost.h"
#include "core/error.h"

enum {                          /* keys of long-only options */
	DEM_OPT_SEED = 256, DEM_OPT_ACCURACY, DEM_OPT_DUMP_SCENE,
	DEM_OPT_VERSION, DEM_OPT_PROGRAM = 300  /* programs number from here */
};

typedef struct dem_opt {
	const char *name;       /* long name, without "--" */
	int key;                /* short letter, or a key >= 256 */
	const char *arg;        /* NULL: no argument; "[X]": optional; "X": required */
	const char *help;       /* one line */
} dem_opt_t;

#define DEM_OPTS_COMMON \
	{"scene", 's', "FILE", "read the scene (YAML) from FILE"}, \
	{"output", 'o', "FILE", "write to FILE (atomically) instead of standard output"}, \
	{"binary", 'b', NULL, "write binary records"}, \
	{"gzip", 'z', NULL, "compress the output with gzip"}, \
	{"seed", DEM_OPT_SEED, "N", "random seed (default: drawn, and written to the header)"}, \
	{"accuracy", DEM_OPT_ACCURACY, "LEVEL", "preset of the accuracy knobs: coarse, normal or fine"}, \
	{"dump-scene", DEM_OPT_DUMP_SCENE, NULL, "print the resolved scene with every default, then exit"}, \
	{"verbose", 'v', NULL, "more detail on standard error"}, \
	{"quiet", 'q', NULL, "no progress messages"}, \
	{"help", 'h', NULL, "print this help and exit"}, \
	{"version", DEM_OPT_VERSION, NULL, "print the version and exit"}

typedef struct dem_cli {
	const char *prog;
	const dem_opt_t *opts;
	struct option *lopts;
	char *sopts;
	int nerr;               /* usage errors so far */
	const char *usage, *purpose, *epilogue;  /* --help texts */
	int done;               /* -1, or the exit code once --help/--version ran */
} dem_cli_t;

enum { DEM_ACCURACY_COARSE, DEM_ACCURACY_NORMAL, DEM_ACCURACY_FINE };

/* A scene key set by an option (see dem_scene_override). */
typedef struct dem_override {
	const char *key, *text, *origin;
} dem_override_t;

/* What the common options say, and the scene keys the program's own
 * options set, in the order typed. */
typedef struct dem_common {
	const char *scene, *output;
	int binary, gzip, dump, verbose, quiet, have_seed, accuracy;
	unsigned long seed;
	dem_override_t *ov;
	int nov, cap;
	char **owned;           /* texts made for overrides, freed with it */
	int nowned;
} dem_common_t;

/* Build the getopt tables; usage, purpose and epilogue (may be NULL) make
 * the --help text.  Returns 0, or -1 when out of memory. */
int dem_cli_init(dem_cli_t *c, const char *prog, const dem_opt_t *opts,
		 const char *usage, const char *purpose, const char *epilogue);
void dem_cli_free(dem_cli_t *c);
/* Next option key (as getopt_long), -1 at the end; an unknown option or a
 * missing argument is counted and reported, and returns '?'. */
int dem_cli_next(dem_cli_t *c, int argc, char **argv);
/* Report a usage error ("prog: message") and count it. */
void dem_cli_error(dem_cli_t *c, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
/* Parse a number in [min, max]; on failure report it (naming the option)
 * and count it.  Return 0 on success. */
int dem_cli_double(dem_cli_t *c, const char *opt, const char *text,
		   double min, double max, double *out);
int dem_cli_ulong(dem_cli_t *c, const char *opt, const char *text,
		  unsigned long min, unsigned long max, unsigned long *out);
/* Print the help: usage lines, purpose, the option table, epilogue. */
void dem_cli_help(const dem_cli_t *c, FILE *f);

/* Room for the overrides of argc arguments; -1 without memory. */
int dem_common_init(dem_common_t *m, int argc);
void dem_common_free(dem_common_t *m);
/* Handle key when it is one of DEM_OPTS_COMMON (returns 1; --help and
 * --version print and set c->done to 0); 0 for the program's own keys. */
int dem_cli_common(dem_cli_t *c, int key, const char *arg, dem_common_t *m);
/* parse_cmdline's loop and its end:
 *
 *	while ((k = dem_cli_option(&c, m, argc, argv)) != -1)
 *		switch (k) { the program's own options }
 *	if (c.done < 0) {
 *		cl->input = dem_cli_operand(&c, argc, argv, "input");
 *		the program's checks of the whole command line
 *	}
 *	return dem_cli_done(&c);
 *
 * dem_cli_option: the next of the program's own option keys, -1 at the
 * end; the common options (DEM_OPTS_COMMON) are handled on the way
 * (dem_cli_common), errors counted.  dem_cli_operand: the one operand of a
 * filter (NULL: none), a second one reported as "unexpected argument 'X'
 * (one WHAT at most)".  dem_cli_done frees c's tables and returns -1 to go
 * on to the work, or the exit code: 0 after --help or --version,
 * DEM_EUSAGE (with the "Try" line) after usage errors. */
int dem_cli_option(dem_cli_t *c, dem_common_t *m, int argc, char **argv);
const char *dem_cli_operand(dem_cli_t *c, int argc, char **argv, const char *what);
int dem_cli_done(dem_cli_t *c);

/* Record that an option sets a scene key. */
void dem_common_override(dem_common_t *m, const char *key, const char *text,
			 const char *origin);
/* The same for "a:b:c" typed for a vector key: kept as "a, b, c".
 * Returns -1 without memory. */
int dem_common_override_vector(dem_common_t *m, const char *key,
			       const char *text, const char *origin);
/* "prog: usage error count"; prints "Try 'prog --help'" and returns
 * DEM_EUSAGE when there were errors, 0 otherwise. */
int dem_cli_finish(const dem_cli_t *c);
/* Print "prog VERSION" on stdout. */
void dem_cli_version(const dem_cli_t *c);
/* Flush and close standard output; a write error is reported and gives
 * DEM_EIO (coreutils' close_stdout). */
int dem_cli_close_stdout(const char *prog);

/* The two ends of a program's main.  dem_cli_end, on success: close
 * standard output when the output went there (no --output), then print the
 * cost line last on stderr (not after --dump-scene, whose scene on standard
 * output is closed whatever -o says); returns the exit code
 * (0, or DEM_EIO on a write error).  dem_cli_fail: report the error as
 * "prog: message", with the "Try 'prog --help'" line for a usage error;
 * returns rc. */
int dem_cli_end(const char *prog, const dem_common_t *m, const dem_cost_t *cost);
int dem_cli_fail(const char *prog, int rc, const dem_error_t *e);

/* A program's main (STYLE.md 2) from its first line to its last:
 *
 *	dem_main_t r;
 *	struct cmdline cl;
 *	int rc;
 *
 *	if ((rc = dem_main_start(&r, PROG, argc, argv)))
 *		return rc;
 *	if ((rc = parse_cmdline(argc, argv, &cl)) >= 0)
 *		return dem_main_quit(&r, &cl.com, rc);
 *	rc = run(&r, &cl);   open, read, compute, write, close; errors in r.e
 *	return dem_main_end(&r, &cl.com, rc);
 *
 * dem_main_start starts the cost clock, turns GSL's aborting error
 * handler off (errors come back as codes) and keeps argv as typed, for
 * the provenance: getopt reorders argv.  DEM_EIO without memory, with
 * nothing to free.  dem_main_quit ends a program that stops before its
 * work (--help, --version, a usage error already reported) with rc;
 * dem_main_end ends the others: a failure (rc != 0) is reported from r->e
 * (dem_cli_fail), a success closes standard output when the output went
 * there and prints the cost line, not after --dump-scene (dem_cli_end).
 * Both free what start made and the common options' overrides, and
 * return the exit code. */
typedef struct dem_main {
	const char *prog;
	int argc;
	char **args;            /* argv as typed, NULL-terminated */
	dem_cost_t cost;
	dem_error_t e;
} dem_main_t;

int dem_main_start(dem_main_t *r, const char *prog, int argc, char **argv);
int dem_main_quit(dem_main_t *r, dem_common_t *m, int rc);
int dem_main_end(dem_main_t *r, dem_common_t *m, int rc);

#endif
