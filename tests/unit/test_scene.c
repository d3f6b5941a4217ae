/* test_scene.c - unit tests of lib/io/scene.c: loading YAML scenes, the typed
 * getters, command-line overrides, the unknown-key check and --dump-scene.
 *
 * Each test writes small scenes into a temporary directory (made with
 * mkdtemp, and made the working directory so messages name "strip.yaml"),
 * and checks values and the exact error messages, with their line:column
 * counted by hand from the YAML text in the test (1-based).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io/scene.h"

struct fixture {
	char dir[64];
	char cwd[4096];
};

static int group_setup(void **state)
{
	static struct fixture fx;

	strcpy(fx.dir, "/tmp/dem-test-scene-XXXXXX");
	if (!getcwd(fx.cwd, sizeof fx.cwd) || !mkdtemp(fx.dir) ||
	    chdir(fx.dir) != 0)
		return -1;
	*state = &fx;
	return 0;
}

static int group_teardown(void **state)
{
	struct fixture *fx = *state;
	char cmd[128];

	if (chdir(fx->cwd) != 0)
		return -1;
	snprintf(cmd, sizeof cmd, "rm -rf '%s'", fx->dir);
	return system(cmd) == 0 ? 0 : -1;
}

static void write_file(const char *name, const char *text)
{
	FILE *f = fopen(name, "w");

	assert_non_null(f);
	assert_int_equal(fputs(text, f) >= 0, 1);
	assert_int_equal(fclose(f), 0);
}

/* Write text to strip.yaml and load it; the load must succeed. */
static dem_scene_t *load(const char *text)
{
	dem_error_t e = { 0, "" };
	dem_scene_t *s = NULL;

	write_file("strip.yaml", text);
	if (dem_scene_load(&s, "strip.yaml", &e) != DEM_OK)
		fail_msg("load failed: %s", e.msg);
	assert_non_null(s);
	return s;
}

/* Write text to strip.yaml; loading it must fail with code and msg. */
static void load_fails(const char *text, int code, const char *msg)
{
	dem_error_t e = { 0, "" };
	dem_scene_t *s = (dem_scene_t *)&e;

	write_file("strip.yaml", text);
	assert_int_equal(dem_scene_load(&s, "strip.yaml", &e), code);
	assert_null(s);
	assert_int_equal(e.code, code);
	assert_string_equal(e.msg, msg);
}

static const char *const laws[] = { "mono", "urd", "nrd", "lnrd", NULL };
static const char *const algos[] = {
	"dcell", "nbs", "scell", "adt", "asdt", "brute", NULL
};

/* ---- loading ----------------------------------------------------------- */

/* A NULL path gives an empty scene: every getter yields its default. */
static void test_null_path_defaults(void **state)
{
	dem_error_t e = { 0, "" };
	dem_scene_t *s;
	double q, v[2], def[2] = { 1, 2 };
	const char *str;
	long n;
	int b, c;

	(void)state;
	assert_int_equal(dem_scene_load(&s, NULL, &e), DEM_OK);
	assert_int_equal(dem_scene_quantity(s, "pack.radius.min",
					    DEM_DIM_LENGTH, 7e-4, 0, HUGE_VAL,
					    &q, &e), DEM_OK);
	assert_true(q == 7e-4);
	assert_int_equal(dem_scene_int(s, "pack.n", 100, 1, LONG_MAX, &n, &e),
			 DEM_OK);
	assert_int_equal(n, 100);
	assert_int_equal(dem_scene_bool(s, "detect.shape", 1, &b, &e), DEM_OK);
	assert_int_equal(b, 1);
	assert_int_equal(dem_scene_choice(s, "detect.algorithm", algos, 0, &c,
					  &e), DEM_OK);
	assert_int_equal(c, 0);
	assert_int_equal(dem_scene_vector(s, "pack.aspect", DEM_DIM_NONE, 2,
					  def, 0, HUGE_VAL, v, &e), DEM_OK);
	assert_true(v[0] == 1 && v[1] == 2);
	assert_int_equal(dem_scene_string(s, "detect.periodic", "xy", &str,
					  &e), DEM_OK);
	assert_string_equal(str, "xy");
	assert_false(dem_scene_has(s, "pack.n"));
	assert_int_equal(e.code, DEM_OK);
	dem_scene_free(s);
}

/* An empty file, a file of comments, a bare "---" and a null document are
 * all empty scenes. */
static void test_empty_files(void **state)
{
	static const char *const texts[] = {
		"", "# only a comment\n\n", "---\n", "~\n", "--- ~\n...\n",
	};
	size_t i;

	(void)state;
	for (i = 0; i < sizeof texts / sizeof texts[0]; i++) {
		dem_scene_t *s = load(texts[i]);
		dem_error_t e = { 0, "" };
		long n;

		assert_int_equal(dem_scene_int(s, "pack.n", 7, 0, 9, &n, &e),
				 DEM_OK);
		assert_int_equal(n, 7);
		assert_int_equal(dem_scene_check(s, NULL, &e), DEM_OK);
		dem_scene_free(s);
	}
}

/* A nonexistent file and a directory are I/O errors with strerror. */
static void test_unreadable(void **state)
{
	dem_error_t e = { 0, "" };
	dem_scene_t *s;

	(void)state;
	assert_int_equal(dem_scene_load(&s, "nonexistent.yaml", &e), DEM_EIO);
	assert_null(s);
	assert_string_equal(e.msg, "nonexistent.yaml: No such file or directory");
	dem_error_clear(&e);
	assert_int_equal(dem_scene_load(&s, ".", &e), DEM_EIO);
	assert_string_equal(e.msg, ".: Is a directory");
}

/* YAML syntax errors give libyaml's problem at its mark, 1-based, with its
 * context. */
static void test_syntax_errors(void **state)
{
	(void)state;
	load_fails("pack:\n  n: [1, 2\n", DEM_EINPUT,
		   "strip.yaml:3:1: did not find expected ',' or ']' (while "
		   "parsing a flow sequence at line 2, column 6)");
	load_fails("pack:\n  n: 1\n bad: 2\n", DEM_EINPUT,
		   "strip.yaml:3:2: did not find expected key (while parsing "
		   "a block mapping at line 1, column 1)");
	load_fails("pack: a: b\n", DEM_EINPUT,
		   "strip.yaml:1:8: mapping values are not allowed in this "
		   "context");
	load_fails("a: \"open\n", DEM_EINPUT,
		   "strip.yaml:2:1: found unexpected end of stream (while "
		   "scanning a quoted scalar at line 1, column 4)");
}

/* Bytes that are not UTF-8: libyaml gives an offset, turned into
 * line:col. */
static void test_bad_utf8(void **state)
{
	(void)state;
	load_fails("pack:\n  n: \xff\xfe\n", DEM_EINPUT,
		   "strip.yaml:2:6: invalid leading UTF-8 octet");
}

/* The top level must be a mapping of sections. */
static void test_top_not_mapping(void **state)
{
	(void)state;
	load_fails("- pack\n- detect\n", DEM_EINPUT,
		   "strip.yaml:1:1: a scene is a mapping of sections (pack:, "
		   "detect:, ...), got a sequence");
	load_fails("\n  5\n", DEM_EINPUT,
		   "strip.yaml:2:3: a scene is a mapping of sections (pack:, "
		   "detect:, ...), got '5'");
}

/* Duplicate keys, at the top and nested, name the key path and the line
 * of the first. */
static void test_duplicate_keys(void **state)
{
	(void)state;
	load_fails("pack:\n  n: 1\n  dim: 2\n  n: 2\n", DEM_EINPUT,
		   "strip.yaml:4:3: duplicate key 'pack.n' (first at line 2)");
	load_fails("pack: {n: 1}\ndetect: {}\npack: {}\n", DEM_EINPUT,
		   "strip.yaml:3:1: duplicate key 'pack' (first at line 1)");
	load_fails("pack:\n  radius: {min: 1, min: 2}\n", DEM_EINPUT,
		   "strip.yaml:2:20: duplicate key 'pack.radius.min' (first "
		   "at line 2)");
	load_fails("pack:\n  seq:\n    - {a: 1, a: 2}\n", DEM_EINPUT,
		   "strip.yaml:3:14: duplicate key 'pack.seq[0].a' (first at "
		   "line 3)");
}

/* Aliases, keys that are not scalars, a second document and absurd
 * nesting are refused. */
static void test_refused_yaml(void **state)
{
	char deep[700];

	(void)state;
	load_fails("pack:\n  n: &x 1\n  dim: *x\n", DEM_EINPUT,
		   "strip.yaml:3:8: aliases (*x) are not supported");
	load_fails("{[a]: 1}\n", DEM_EINPUT,
		   "strip.yaml:1:2: a key must be a name, got a sequence");
	load_fails("pack: {}\n---\ndetect: {}\n", DEM_EINPUT,
		   "strip.yaml:2:1: a second document; a scene is one YAML "
		   "document");
	memset(deep, '[', 300);
	memset(deep + 300, ']', 300);
	strcpy(deep + 600, "\n");
	load_fails(deep, DEM_EINPUT,
		   "strip.yaml:1:257: nested deeper than 256 levels");
}

/* ---- getters ------------------------------------------------------------ */

/* Quantities: units convert to SI, a bare number is SI, quoted text is
 * read the same, and absent keys give the default. */
static void test_quantity(void **state)
{
	dem_scene_t *s = load("pack:\n"
			      "  radius:\n"
			      "    min: 0.7 mm\n"
			      "    max: 0.002\n"
			      "shot:\n"
			      "  speed: \"46.5 m/s\"\n"
			      "  angle: 30 deg\n"
			      "material:\n"
			      "  E: 72 GPa\n"
			      "  rho: 7800 kg/m^3\n");
	dem_error_t e = { 0, "" };
	double v;

	(void)state;
	assert_int_equal(dem_scene_quantity(s, "pack.radius.min",
					    DEM_DIM_LENGTH, 1, 0, HUGE_VAL,
					    &v, &e), DEM_OK);
	assert_true(v == 0.0007);
	assert_int_equal(dem_scene_quantity(s, "pack.radius.max",
					    DEM_DIM_LENGTH, 1, 0, HUGE_VAL,
					    &v, &e), DEM_OK);
	assert_true(v == 0.002);
	assert_int_equal(dem_scene_quantity(s, "shot.speed", DEM_DIM_VELOCITY,
					    0, 0, HUGE_VAL, &v, &e), DEM_OK);
	assert_true(v == 46.5);
	assert_int_equal(dem_scene_quantity(s, "shot.angle", DEM_DIM_ANGLE, 0,
					    -HUGE_VAL, HUGE_VAL, &v, &e),
			 DEM_OK);
	assert_true(v == 30 * (3.14159265358979323846 / 180));
	assert_int_equal(dem_scene_quantity(s, "material.E", DEM_DIM_PRESSURE,
					    0, 0, HUGE_VAL, &v, &e), DEM_OK);
	assert_true(v == 72e9);
	assert_int_equal(dem_scene_quantity(s, "material.rho",
					    DEM_DIM_DENSITY, 0, 0, HUGE_VAL,
					    &v, &e), DEM_OK);
	assert_true(v == 7800);
	assert_int_equal(dem_scene_quantity(s, "material.nu", DEM_DIM_NONE,
					    0.3, 0, 0.5, &v, &e), DEM_OK);
	assert_true(v == 0.3);
	dem_scene_free(s);
}

/* A quantity getter that must fail on key in the given scene with the
 * exact message. */
static void quantity_fails(const char *text, const char *key, dem_dim_t dim,
			   double min, double max, const char *msg)
{
	dem_scene_t *s = load(text);
	dem_error_t e = { 0, "" };
	double v = -1;

	assert_int_equal(dem_scene_quantity(s, key, dim, 1, min, max, &v, &e),
			 DEM_EINPUT);
	assert_true(v == -1);
	assert_string_equal(e.msg, msg);
	dem_scene_free(s);
}

/* Wrong unit, unknown unit, not a number, not finite: file:line:col (of
 * the value), the key, and the expected form with an example. */
static void test_quantity_errors(void **state)
{
	(void)state;
	quantity_fails("shot:\n\n\n\n\n\n  speed: 1 mm\n", "shot.speed",
		       DEM_DIM_VELOCITY, 0, HUGE_VAL,
		       "strip.yaml:7:10: shot.speed: unit 'mm' is a length, "
		       "expected a velocity (e.g. '46.5 m/s')");
	quantity_fails("shot:\n  speed: fast\n", "shot.speed",
		       DEM_DIM_VELOCITY, 0, HUGE_VAL,
		       "strip.yaml:2:10: shot.speed: expected a velocity (e.g. "
		       "'46.5 m/s'), got 'fast' (not a number)");
	quantity_fails("shot:\n  speed: 46.5 mph\n", "shot.speed",
		       DEM_DIM_VELOCITY, 0, HUGE_VAL,
		       "strip.yaml:2:10: shot.speed: expected a velocity (e.g. "
		       "'46.5 m/s'), got '46.5 mph' (unknown unit 'mph')");
	quantity_fails("shot:\n  speed: .nan\n", "shot.speed",
		       DEM_DIM_VELOCITY, 0, HUGE_VAL,
		       "strip.yaml:2:10: shot.speed: expected a velocity (e.g. "
		       "'46.5 m/s'), got '.nan' (not finite)");
	quantity_fails("pack:\n  radius:\n    min: 0.7 mm;\n",
		       "pack.radius.min", DEM_DIM_LENGTH, 0, HUGE_VAL,
		       "strip.yaml:3:10: pack.radius.min: expected a length "
		       "(e.g. '0.7 mm'), got '0.7 mm;' (trailing garbage ';')");
	quantity_fails("material:\n  visc: 1 Pa\n", "material.visc",
		       (dem_dim_t){ -1, 1, -1, 0, 0 }, 0, HUGE_VAL,
		       "strip.yaml:2:9: material.visc: unit 'Pa' is a pressure, "
		       "expected a quantity in m^-1 kg s^-1 (e.g. "
		       "'1 m^-1 kg s^-1')");
}

/* Wrong types: a mapping, a sequence or an empty value where a quantity
 * is expected. */
static void test_quantity_types(void **state)
{
	(void)state;
	quantity_fails("pack:\n  density:\n    a: 1\n", "pack.density",
		       DEM_DIM_NONE, 0, 1,
		       "strip.yaml:3:5: pack.density: expected a number (e.g. "
		       "'0.5'), got a mapping");
	quantity_fails("pack:\n  density: [1, 2]\n", "pack.density",
		       DEM_DIM_NONE, 0, 1,
		       "strip.yaml:2:12: pack.density: expected a number (e.g. "
		       "'0.5'), got a sequence");
	quantity_fails("pack:\n  density:\n", "pack.density", DEM_DIM_NONE, 0,
		       1, "strip.yaml:2:11: pack.density: expected a number "
		       "(e.g. '0.5'), got an empty value");
	quantity_fails("pack:\n  density: ''\n", "pack.density", DEM_DIM_NONE,
		       0, 1, "strip.yaml:2:12: pack.density: expected a number "
		       "(e.g. '0.5'), got '' (not a number)");
	/* a part of the path that is not a mapping */
	quantity_fails("pack: 5\n", "pack.radius.min", DEM_DIM_LENGTH, 0,
		       HUGE_VAL, "strip.yaml:1:7: pack: expected a mapping, "
		       "got '5'");
	quantity_fails("pack:\n  radius: [1]\n", "pack.radius.min",
		       DEM_DIM_LENGTH, 0, HUGE_VAL,
		       "strip.yaml:2:11: pack.radius: expected a mapping, got "
		       "a sequence");
}

/* Ranges are inclusive; infinite bounds read "at least"/"at most", the
 * DEM_SCENE_GT0 bound reads "(0", and a value with a unit shows its SI
 * value too. */
static void test_quantity_range(void **state)
{
	dem_scene_t *s = load("pack:\n  density: 1\n  zero: 0\n");
	dem_error_t e = { 0, "" };
	double v;

	(void)state;
	/* the bounds themselves are in range */
	assert_int_equal(dem_scene_quantity(s, "pack.density", DEM_DIM_NONE,
					    0.5, 0, 1, &v, &e), DEM_OK);
	assert_true(v == 1);
	assert_int_equal(dem_scene_quantity(s, "pack.zero", DEM_DIM_NONE, 0.5,
					    0, 1, &v, &e), DEM_OK);
	assert_true(v == 0);
	dem_scene_free(s);

	quantity_fails("\n\n\n\n\n\n\n\n\n\npack:\n  density: 1.5\n",
		       "pack.density", DEM_DIM_NONE, 0, 1,
		       "strip.yaml:12:12: pack.density: 1.5 is out of range, "
		       "expected a number in [0, 1]");
	quantity_fails("pack:\n  density: 0\n", "pack.density", DEM_DIM_NONE,
		       DEM_SCENE_GT0, 1,
		       "strip.yaml:2:12: pack.density: 0 is out of range, "
		       "expected a number in (0, 1]");
	quantity_fails("pack:\n  cell: 0 mm\n", "pack.cell", DEM_DIM_LENGTH,
		       DEM_SCENE_GT0, HUGE_VAL,
		       "strip.yaml:2:9: pack.cell: 0 mm (= 0 m) is out of range, "
		       "expected a length greater than 0 m");
	quantity_fails("pack:\n  min: -1 mm\n", "pack.min", DEM_DIM_LENGTH, 0,
		       HUGE_VAL,
		       "strip.yaml:2:8: pack.min: -1 mm (= -0.001 m) is out of "
		       "range, expected a length of at least 0 m");
	quantity_fails("shot:\n  angle: 100 deg\n", "shot.angle",
		       DEM_DIM_ANGLE, -HUGE_VAL, 1.5,
		       "strip.yaml:2:10: shot.angle: 100 deg (= "
		       "1.7453292519943295 rad) is out of range, expected an "
		       "angle of at most 1.5 rad");
	quantity_fails("material:\n  E: 1 Pa\n", "material.E",
		       DEM_DIM_PRESSURE, 1e9, 1e12,
		       "strip.yaml:2:6: material.E: 1 Pa (= 1 Pa) is out of "
		       "range, expected a pressure in [1000000000, "
		       "1000000000000] Pa");
}

/* Integers: decimal, or a number that is an integer ("1e6"); fractions,
 * words and out-of-range values are refused. */
static void test_int(void **state)
{
	dem_scene_t *s = load("pack:\n  n: 1000\n  m: 1e6\n  k: -3\n"
			      "  f: 2.5\n  w: many\n  z: 0\n"
			      "  h: 99999999999999999999\n  q: {a: 1}\n");
	dem_error_t e = { 0, "" };
	long n;

	(void)state;
	assert_int_equal(dem_scene_int(s, "pack.n", 1, 1, LONG_MAX, &n, &e), 0);
	assert_int_equal(n, 1000);
	assert_int_equal(dem_scene_int(s, "pack.m", 1, 1, LONG_MAX, &n, &e), 0);
	assert_int_equal(n, 1000000);
	assert_int_equal(dem_scene_int(s, "pack.k", 1, LONG_MIN, LONG_MAX, &n,
				       &e), 0);
	assert_int_equal(n, -3);
	assert_int_equal(dem_scene_int(s, "pack.absent", 42, 1, 2, &n, &e), 0);
	assert_int_equal(n, 42);

	assert_int_equal(dem_scene_int(s, "pack.f", 1, 1, 9, &n, &e),
			 DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:5:6: pack.f: expected an "
			    "integer, got '2.5'");
	dem_error_clear(&e);
	assert_int_equal(dem_scene_int(s, "pack.w", 1, 1, 9, &n, &e),
			 DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:6:6: pack.w: expected an "
			    "integer, got 'many'");
	dem_error_clear(&e);
	assert_int_equal(dem_scene_int(s, "pack.z", 1, 1, LONG_MAX, &n, &e),
			 DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:7:6: pack.z: 0 is out of range, "
			    "expected an integer of at least 1");
	dem_error_clear(&e);
	assert_int_equal(dem_scene_int(s, "pack.n", 1, 2, 3, &n, &e),
			 DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:2:6: pack.n: 1000 is out of "
			    "range, expected an integer in [2, 3]");
	dem_error_clear(&e);
	assert_int_equal(dem_scene_int(s, "pack.n", 1, LONG_MIN, 10, &n, &e),
			 DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:2:6: pack.n: 1000 is out of "
			    "range, expected an integer of at most 10");
	dem_error_clear(&e);
	assert_int_equal(dem_scene_int(s, "pack.h", 1, LONG_MIN, LONG_MAX, &n,
				       &e), DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:8:6: pack.h: "
			    "99999999999999999999 is out of range, expected an "
			    "integer");
	dem_error_clear(&e);
	assert_int_equal(dem_scene_int(s, "pack.q", 1, 1, 9, &n, &e),
			 DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:9:6: pack.q: expected an "
			    "integer, got a mapping");
	dem_scene_free(s);
}

/* Booleans: true/false/yes/no in any case; anything else is refused. */
static void test_bool(void **state)
{
	dem_scene_t *s = load("detect:\n  a: true\n  b: no\n  c: Yes\n"
			      "  d: FALSE\n  e: maybe\n  f: 1\n");
	dem_error_t e = { 0, "" };
	int b;

	(void)state;
	assert_int_equal(dem_scene_bool(s, "detect.a", 0, &b, &e), 0);
	assert_int_equal(b, 1);
	assert_int_equal(dem_scene_bool(s, "detect.b", 1, &b, &e), 0);
	assert_int_equal(b, 0);
	assert_int_equal(dem_scene_bool(s, "detect.c", 0, &b, &e), 0);
	assert_int_equal(b, 1);
	assert_int_equal(dem_scene_bool(s, "detect.d", 1, &b, &e), 0);
	assert_int_equal(b, 0);
	assert_int_equal(dem_scene_bool(s, "detect.x", 1, &b, &e), 0);
	assert_int_equal(b, 1);
	assert_int_equal(dem_scene_bool(s, "detect.e", 0, &b, &e), DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:6:6: detect.e: expected true or "
			    "false (or yes, no), got 'maybe'");
	dem_error_clear(&e);
	assert_int_equal(dem_scene_bool(s, "detect.f", 0, &b, &e), DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:7:6: detect.f: expected true or "
			    "false (or yes, no), got '1'");
	dem_scene_free(s);
}

/* Choices: the index of the name; a wrong name lists the allowed ones. */
static void test_choice(void **state)
{
	dem_scene_t *s = load("detect:\n  algorithm: asdt\n  other: ADT\n");
	dem_error_t e = { 0, "" };
	int c;

	(void)state;
	assert_int_equal(dem_scene_choice(s, "detect.algorithm", algos, 0, &c,
					  &e), 0);
	assert_int_equal(c, 4);
	assert_int_equal(dem_scene_choice(s, "pack.radius.law", laws, 1, &c,
					  &e), 0);
	assert_int_equal(c, 1);
	assert_int_equal(dem_scene_choice(s, "detect.other", algos, 0, &c, &e),
			 DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:3:10: detect.other: expected one "
			    "of dcell, nbs, scell, adt, asdt, brute, got 'ADT'");
	dem_scene_free(s);
}

/* Vectors: flow and block sequences of exactly n quantities, each with
 * its own unit; errors name the item and its position. */
static void test_vector(void **state)
{
	dem_scene_t *s = load("pack:\n"
			      "  aspect: [1, 2]\n"
			      "  box:\n"
			      "    - 1 mm\n"
			      "    - 2 cm\n"
			      "    - 3\n"
			      "  short: [1 mm]\n"
			      "  bad: [1 mm, 2 s, 3 mm]\n"
			      "  neg: [1, -1]\n"
			      "  nested: [1, [2]]\n"
			      "  map: {a: 1}\n");
	dem_error_t e = { 0, "" };
	double v[3] = { 0, 0, 0 }, def[3] = { 7, 8, 9 };

	(void)state;
	assert_int_equal(dem_scene_vector(s, "pack.aspect", DEM_DIM_NONE, 2,
					  def, 0, HUGE_VAL, v, &e), 0);
	assert_true(v[0] == 1 && v[1] == 2);
	assert_int_equal(dem_scene_vector(s, "pack.box", DEM_DIM_LENGTH, 3,
					  def, 0, HUGE_VAL, v, &e), 0);
	assert_true(v[0] == 0.001 && v[1] == 0.02 && v[2] == 3);
	assert_int_equal(dem_scene_vector(s, "pack.none", DEM_DIM_LENGTH, 3,
					  def, 0, HUGE_VAL, v, &e), 0);
	assert_true(v[0] == 7 && v[1] == 8 && v[2] == 9);

	assert_int_equal(dem_scene_vector(s, "pack.short", DEM_DIM_LENGTH, 3,
					  def, 0, HUGE_VAL, v, &e), DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:7:10: pack.short: expected 3 "
			    "lengths (e.g. '[0.7 mm, 0.7 mm, 0.7 mm]'), got a "
			    "sequence of 1");
	dem_error_clear(&e);
	assert_int_equal(dem_scene_vector(s, "pack.bad", DEM_DIM_LENGTH, 3,
					  def, 0, HUGE_VAL, v, &e), DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:8:15: pack.bad[1]: unit 's' is "
			    "a time, expected a length (e.g. '0.7 mm')");
	/* out is written only when every item is good */
	assert_true(v[0] == 7 && v[1] == 8 && v[2] == 9);
	dem_error_clear(&e);
	assert_int_equal(dem_scene_vector(s, "pack.neg", DEM_DIM_NONE, 2, def,
					  0, HUGE_VAL, v, &e), DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:9:12: pack.neg[1]: -1 is out of "
			    "range, expected a number of at least 0");
	dem_error_clear(&e);
	assert_int_equal(dem_scene_vector(s, "pack.nested", DEM_DIM_NONE, 2,
					  def, 0, HUGE_VAL, v, &e), DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:10:15: pack.nested[1]: expected "
			    "a number, got a sequence");
	dem_error_clear(&e);
	assert_int_equal(dem_scene_vector(s, "pack.map", DEM_DIM_NONE, 2, def,
					  0, HUGE_VAL, v, &e), DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:11:8: pack.map: expected 2 "
			    "numbers (e.g. '[0.5, 0.5]'), got a mapping");
	dem_scene_free(s);
}

/* A vector may be one scalar, "[1, 2] mm" or "1, 2", as the command line
 * gives it; a NULL default leaves out untouched. */
static void test_vector_scalar(void **state)
{
	dem_scene_t *s = load("pack:\n  a: 1, 2\n  b: '[1, 2] mm'\n"
			      "  c: '[1 mm, 2 mm]'\n  d: '[1, 2'\n");
	dem_error_t e = { 0, "" };
	double v[2] = { -1, -1 };

	(void)state;
	assert_int_equal(dem_scene_vector(s, "pack.absent", DEM_DIM_NONE, 2,
					  NULL, 0, HUGE_VAL, v, &e), 0);
	assert_true(v[0] == -1 && v[1] == -1);
	assert_int_equal(dem_scene_vector(s, "pack.a", DEM_DIM_NONE, 2, NULL,
					  0, HUGE_VAL, v, &e), 0);
	assert_true(v[0] == 1 && v[1] == 2);
	assert_int_equal(dem_scene_vector(s, "pack.b", DEM_DIM_LENGTH, 2, NULL,
					  0, HUGE_VAL, v, &e), 0);
	assert_true(v[0] == 0.001 && v[1] == 0.002);
	assert_int_equal(dem_scene_vector(s, "pack.c", DEM_DIM_LENGTH, 2, NULL,
					  0, HUGE_VAL, v, &e), 0);
	assert_true(v[0] == 0.001 && v[1] == 0.002);
	assert_int_equal(dem_scene_vector(s, "pack.d", DEM_DIM_LENGTH, 2, NULL,
					  0, HUGE_VAL, v, &e), DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:5:6: pack.d: expected 2 lengths "
			    "(e.g. '[0.7 mm, 0.7 mm]'), got '[1, 2'");
	dem_error_clear(&e);
	assert_int_equal(dem_scene_vector(s, "pack.a", DEM_DIM_NONE, 3, NULL,
					  0, HUGE_VAL, v, &e), DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:2:6: pack.a: expected 3 numbers "
			    "(e.g. '[0.5, 0.5, 0.5]'), got '1, 2'");
	dem_scene_free(s);
}

/* Strings: any scalar, quoted or not (a quoted empty string too); not a
 * mapping or an empty value.  The result outlives overrides. */
static void test_string(void **state)
{
	dem_scene_t *s = load("detect:\n  periodic: xy\n  empty: ''\n"
			      "  map: {a: 1}\n  null:\n");
	dem_error_t e = { 0, "" };
	const char *str, *first;

	(void)state;
	assert_int_equal(dem_scene_string(s, "detect.periodic", "", &first,
					  &e), 0);
	assert_string_equal(first, "xy");
	assert_int_equal(dem_scene_string(s, "detect.empty", "z", &str, &e), 0);
	assert_string_equal(str, "");
	assert_int_equal(dem_scene_string(s, "detect.absent", NULL, &str, &e),
			 0);
	assert_null(str);
	assert_int_equal(dem_scene_string(s, "detect.map", "", &str, &e),
			 DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:4:8: detect.map: expected a "
			    "string, got a mapping");
	dem_error_clear(&e);
	assert_int_equal(dem_scene_string(s, "detect.null", "", &str, &e),
			 DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:5:8: detect.null: expected a "
			    "string, got an empty value");
	dem_error_clear(&e);
	/* replacing the node must not free the string handed out */
	assert_int_equal(dem_scene_override(s, "detect.periodic", "z", "-p",
					    &e), 0);
	assert_string_equal(first, "xy");
	dem_scene_free(s);
}

/* A program's own complaint about a value is placed at the value: its
 * file:line:col, its option, or nowhere for a default. */
static void test_scene_error(void **state)
{
	dem_scene_t *s = load("detect:\n  periodic: xq\n");
	dem_error_t e = { 0, "" };

	(void)state;
	assert_int_equal(dem_scene_error(s, "detect.periodic", &e, "'%s': "
					 "expected axes among x, y, z", "xq"),
			 DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:2:13: detect.periodic: 'xq': "
			    "expected axes among x, y, z");
	dem_error_clear(&e);
	assert_int_equal(dem_scene_override(s, "detect.periodic", "w",
					    "--periodic", &e), 0);
	/* a bad value typed on the command line is a usage error */
	assert_int_equal(dem_scene_error(s, "detect.periodic", &e, "bad"),
			 DEM_EUSAGE);
	assert_string_equal(e.msg, "command line: --periodic: detect.periodic: "
			    "bad");
	dem_error_clear(&e);
	assert_int_equal(dem_scene_error(s, "detect.cell", &e, "too small"),
			 DEM_EINPUT);
	assert_string_equal(e.msg, "detect.cell: too small");
	dem_scene_free(s);
}

/* ---- overrides ----------------------------------------------------------- */

/* An override replaces the file's value, creates missing mappings, and
 * its errors name the option instead of file:line:col. */
static void test_override(void **state)
{
	dem_scene_t *s = load("pack:\n  density: 0.5\n  n: 10\nmeta:\n");
	dem_error_t e = { 0, "" };
	double v;
	long n;

	(void)state;
	assert_int_equal(dem_scene_override(s, "pack.density", "0.25",
					    "--density", &e), 0);
	assert_int_equal(dem_scene_override(s, "pack.radius.min", "1 mm",
					    "--rmin", &e), 0);
	assert_int_equal(dem_scene_override(s, "meta.x", "1", "--x", &e), 0);
	assert_true(dem_scene_has(s, "pack.radius.min"));
	assert_true(dem_scene_has(s, "meta.x"));
	assert_int_equal(dem_scene_quantity(s, "pack.density", DEM_DIM_NONE, 1,
					    0, 1, &v, &e), 0);
	assert_true(v == 0.25);
	assert_int_equal(dem_scene_quantity(s, "pack.radius.min",
					    DEM_DIM_LENGTH, 1, 0, HUGE_VAL,
					    &v, &e), 0);
	assert_true(v == 0.001);
	assert_int_equal(dem_scene_int(s, "pack.n", 1, 1, 100, &n, &e), 0);
	assert_int_equal(n, 10);

	assert_int_equal(dem_scene_override(s, "pack.density", "1.5",
					    "--density", &e), 0);
	assert_int_equal(dem_scene_quantity(s, "pack.density", DEM_DIM_NONE, 1,
					    0, 1, &v, &e), DEM_EUSAGE);
	assert_string_equal(e.msg, "command line: --density: pack.density: 1.5 "
			    "is out of range, expected a number in [0, 1]");
	dem_error_clear(&e);
	assert_int_equal(dem_scene_override(s, "pack.radius.min", "1 s",
					    "--rmin", &e), 0);
	assert_int_equal(dem_scene_quantity(s, "pack.radius.min",
					    DEM_DIM_LENGTH, 1, 0, HUGE_VAL,
					    &v, &e), DEM_EUSAGE);
	assert_string_equal(e.msg, "command line: --rmin: pack.radius.min: "
			    "unit 's' is a time, expected a length (e.g. "
			    "'0.7 mm')");
	dem_scene_free(s);
}

/* An override cannot go through a scalar of the file, and a malformed key
 * is a usage error. */
static void test_override_errors(void **state)
{
	dem_scene_t *s = load("pack:\n  n: 10\n");
	dem_error_t e = { 0, "" };

	(void)state;
	assert_int_equal(dem_scene_override(s, "pack.n.x", "1", "--x", &e),
			 DEM_EUSAGE);
	assert_string_equal(e.msg, "command line: --x: cannot set pack.n.x: "
			    "pack.n is '10' (strip.yaml:2:6)");
	dem_error_clear(&e);
	assert_int_equal(dem_scene_override(s, "pack..n", "1", "--n", &e),
			 DEM_EUSAGE);
	assert_string_equal(e.msg, "command line: --n: bad scene key 'pack..n'");
	dem_error_clear(&e);
	assert_int_equal(dem_scene_override(s, "", "1", "--n", &e), DEM_EUSAGE);
	dem_error_clear(&e);
	/* a vector from the command line, and a whole mapping replaced */
	assert_int_equal(dem_scene_override(s, "pack.aspect", "[1, 3]",
					    "--aspect", &e), 0);
	assert_int_equal(dem_scene_override(s, "pack", "x", "--pack", &e), 0);
	assert_false(dem_scene_has(s, "pack.n"));
	assert_true(dem_scene_has(s, "pack"));
	dem_scene_free(s);
}

/* ---- dem_scene_check ----------------------------------------------------- */

/* Read the pack keys a packing program would read. */
static void read_pack(dem_scene_t *s, dem_error_t *e)
{
	double v, asp[2], one[2] = { 1, 1 };
	long n;
	int c;

	assert_int_equal(dem_scene_int(s, "pack.dim", 2, 2, 3, &n, e), 0);
	assert_int_equal(dem_scene_int(s, "pack.n", 100, 1, LONG_MAX, &n, e), 0);
	assert_int_equal(dem_scene_quantity(s, "pack.density", DEM_DIM_NONE,
					    0.5, DEM_SCENE_GT0, 1, &v, e), 0);
	assert_int_equal(dem_scene_vector(s, "pack.aspect", DEM_DIM_NONE, 2,
					  one, 0, HUGE_VAL, asp, e), 0);
	assert_int_equal(dem_scene_choice(s, "pack.radius.law", laws, 0, &c,
					  e), 0);
	assert_int_equal(dem_scene_quantity(s, "pack.radius.min",
					    DEM_DIM_LENGTH, 1e-3, 0, HUGE_VAL,
					    &v, e), 0);
}

static const char *const pack_only[] = { "pack", NULL };

/* Keys read are accepted; a misspelt key is reported at its position
 * with the keys read in that mapping, sorted. */
static void test_check_unknown_key(void **state)
{
	dem_scene_t *s = load("pack:\n  dim: 2\n  n: 10\n  denisty: 0.5\n");
	dem_error_t e = { 0, "" };

	(void)state;
	read_pack(s, &e);
	assert_int_equal(dem_scene_check(s, pack_only, &e), DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:4:3: unknown key 'pack.denisty'; "
			    "known keys here: aspect, density, dim, n, radius");
	dem_scene_free(s);
	dem_error_clear(&e);

	s = load("pack:\n  radius:\n    law: urd\n    mn: 1 mm\n");
	read_pack(s, &e);
	assert_int_equal(dem_scene_check(s, pack_only, &e), DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:4:5: unknown key "
			    "'pack.radius.mn'; known keys here: law, min");
	dem_scene_free(s);
	dem_error_clear(&e);

	/* a mapping where none of its keys were read */
	s = load("pack:\n  extra:\n    a: 1\n");
	read_pack(s, &e);
	assert_int_equal(dem_scene_check(s, pack_only, &e), DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:2:3: unknown key 'pack.extra'; "
			    "known keys here: aspect, density, dim, n, radius");
	dem_scene_free(s);
}

/* Only the listed sections are checked; every section must be known; a
 * null section is an empty one. */
static void test_check_sections(void **state)
{
	dem_scene_t *s = load("pack:\n  n: 5\n  radius:\nshot:\n  anything: 1\n"
			      "meta:\n  title: x\n");
	dem_error_t e = { 0, "" };

	(void)state;
	read_pack(s, &e);
	assert_int_equal(dem_scene_check(s, pack_only, &e), DEM_OK);
	dem_scene_free(s);
	dem_error_clear(&e);

	/* an unknown section fails the load: before any getter could call a
	 * key of the section meant missing */
	load_fails("pack:\n  n: 5\ndetect: {}\n\npakc:\n  n: 5\n", DEM_EINPUT,
		   "strip.yaml:5:1: unknown section 'pakc' (did you mean 'pack'?); "
		   "known sections: pack, detect, shot, block, "
		   "material, contact, run, load, profile, form, plate, "
		   "output, meta, bodies, walls, dim");
	load_fails("block:\n  element: 0.1 mm\nmeta:\n  title: x\n  blokc: 1\n"
		   "blokc:\n  size: 1 mm\n", DEM_EINPUT,
		   "strip.yaml:6:1: unknown section 'blokc' (did you mean 'block'?); "
		   "known sections: pack, detect, shot, block, "
		   "material, contact, run, load, profile, form, plate, "
		   "output, meta, bodies, walls, dim");
	/* no hint for a word that is not near a section */
	load_fails("pack:\n  n: 5\nfrobnicate: 1\n", DEM_EINPUT,
		   "strip.yaml:3:1: unknown section 'frobnicate'; "
		   "known sections: pack, detect, shot, block, "
		   "material, contact, run, load, profile, form, plate, "
		   "output, meta, bodies, walls, dim");

	/* a section that is not a mapping */
	s = load("pack: 5\n");
	assert_int_equal(dem_scene_check(s, pack_only, &e), DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:1:7: pack: expected a mapping, "
			    "got '5'");
	dem_scene_free(s);
	dem_error_clear(&e);

	/* nothing read in a section: every key is unknown */
	s = load("detect:\n  algo: nbs\n");
	assert_int_equal(dem_scene_check(s, (const char *const[]){ "detect",
				NULL }, &e), DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:2:3: unknown key 'detect.algo'; "
			    "no keys are read here");
	dem_scene_free(s);
}

/* An unknown key set on the command line is reported with the option. */
static void test_check_override(void **state)
{
	dem_scene_t *s = load("pack:\n  n: 5\n");
	dem_error_t e = { 0, "" };

	(void)state;
	assert_int_equal(dem_scene_override(s, "pack.foo", "1", "--foo", &e), 0);
	read_pack(s, &e);
	assert_int_equal(dem_scene_check(s, pack_only, &e), DEM_EUSAGE);
	assert_string_equal(e.msg, "command line: --foo: unknown key "
			    "'pack.foo'; known keys here: aspect, density, dim, "
			    "n, radius");
	dem_scene_free(s);
	dem_error_clear(&e);

	s = load("pack:\n  n: 5\n");
	assert_int_equal(dem_scene_override(s, "blob.x", "1", "--blob", &e), 0);
	assert_int_equal(dem_scene_check(s, NULL, &e), DEM_EUSAGE);
	assert_string_equal(e.msg, "command line: --blob: unknown section "
			    "'blob'; known sections: pack, detect, shot, block, "
			    "material, contact, run, load, profile, form, plate, "
			    "output, meta, bodies, walls, dim");
	dem_scene_free(s);
}

/* ---- dem_scene_dump ------------------------------------------------------ */

static char *dump_to_string(const dem_scene_t *s)
{
	char *buf = NULL;
	size_t len = 0;
	FILE *f = open_memstream(&buf, &len);

	assert_non_null(f);
	dem_scene_dump(s, f);
	assert_int_equal(fclose(f), 0);
	return buf;
}

/* The values a program reads, with defaults chosen to differ from the
 * file so that a reload of the dump is seen to take the dumped value. */
struct values {
	double rmin, dens, speed, angle, rho, grav[3], asp[2], odd;
	long n;
	int shape, law, algo;
	const char *periodic, *title;
};

static void read_values(dem_scene_t *s, struct values *v, double def)
{
	dem_error_t e = { 0, "" };
	double zero[3] = { def, def, def };

	assert_int_equal(dem_scene_quantity(s, "pack.radius.min",
					    DEM_DIM_LENGTH, def, 0, HUGE_VAL,
					    &v->rmin, &e), 0);
	assert_int_equal(dem_scene_int(s, "pack.n", (long)def, 0, LONG_MAX,
				       &v->n, &e), 0);
	assert_int_equal(dem_scene_quantity(s, "pack.density", DEM_DIM_NONE,
					    def, 0, HUGE_VAL, &v->dens, &e), 0);
	assert_int_equal(dem_scene_choice(s, "pack.radius.law", laws,
					  (int)def % 4, &v->law, &e), 0);
	assert_int_equal(dem_scene_vector(s, "pack.aspect", DEM_DIM_NONE, 2,
					  zero, 0, HUGE_VAL, v->asp, &e), 0);
	assert_int_equal(dem_scene_choice(s, "detect.algorithm", algos,
					  (int)def % 6, &v->algo, &e), 0);
	assert_int_equal(dem_scene_bool(s, "detect.shape", def > 1, &v->shape,
					&e), 0);
	assert_int_equal(dem_scene_string(s, "detect.periodic", "", &v->periodic,
					  &e), 0);
	assert_int_equal(dem_scene_quantity(s, "shot.speed", DEM_DIM_VELOCITY,
					    def, 0, HUGE_VAL, &v->speed, &e), 0);
	assert_int_equal(dem_scene_quantity(s, "shot.angle", DEM_DIM_ANGLE, def,
					    -HUGE_VAL, HUGE_VAL, &v->angle, &e),
			 0);
	assert_int_equal(dem_scene_quantity(s, "material.rho", DEM_DIM_DENSITY,
					    def, 0, HUGE_VAL, &v->rho, &e), 0);
	assert_int_equal(dem_scene_vector(s, "run.gravity", DEM_DIM_ACCEL, 3,
					  zero, -HUGE_VAL, HUGE_VAL, v->grav,
					  &e), 0);
	assert_int_equal(dem_scene_quantity(s, "material.visc",
					    (dem_dim_t){ -1, 1, -1, 0, 0 }, def,
					    0, HUGE_VAL, &v->odd, &e), 0);
	assert_int_equal(dem_scene_string(s, "meta.title", "", &v->title, &e),
			 0);
	/* asked twice: printed once */
	assert_int_equal(dem_scene_int(s, "pack.n", (long)def, 0, LONG_MAX,
				       &v->n, &e), 0);
}

static void assert_same_values(const struct values *a, const struct values *b)
{
	int i;

	assert_true(a->rmin == b->rmin && a->dens == b->dens);
	assert_true(a->speed == b->speed && a->angle == b->angle);
	assert_true(a->rho == b->rho && a->odd == b->odd);
	for (i = 0; i < 3; i++)
		assert_true(a->grav[i] == b->grav[i]);
	assert_true(a->asp[0] == b->asp[0] && a->asp[1] == b->asp[1]);
	assert_int_equal(a->n, b->n);
	assert_int_equal(a->shape, b->shape);
	assert_int_equal(a->law, b->law);
	assert_int_equal(a->algo, b->algo);
	assert_string_equal(a->periodic, b->periodic);
	assert_string_equal(a->title, b->title);
}

/* The dump is nested YAML in the order keys were first asked, SI values
 * with their units, a key asked twice printed once. */
static void test_dump_format(void **state)
{
	dem_scene_t *s = load("pack:\n  radius:\n    min: 0.7 mm\n"
			      "  density: 0.1\n"
			      "detect:\n  periodic: 'x: y'\n"
			      "shot:\n  speed: 46.5 m/s\n  angle: 90 deg\n"
			      "material:\n  visc: 2 m^-1 kg s^-1\n"
			      "meta:\n  title: \"a \\\"b\\\"\\n\"\n");
	struct values v;
	char *out;

	(void)state;
	read_values(s, &v, 3);
	out = dump_to_string(s);
	assert_string_equal(out,
		"pack:\n"
		"  radius:\n"
		"    min: 0.0007 m\n"
		"    law: lnrd\n"
		"  n: 3\n"
		"  density: 0.1\n"
		"  aspect: [3, 3]\n"
		"detect:\n"
		"  algorithm: adt\n"
		"  shape: true\n"
		"  periodic: \"x: y\"\n"
		"shot:\n"
		"  speed: 46.5 m/s\n"
		"  angle: 1.5707963267948966 rad\n"
		"material:\n"
		"  rho: 3 kg/m^3\n"
		"  visc: 2 m^-1 kg s^-1\n"
		"run:\n"
		"  gravity: [3 m/s^2, 3 m/s^2, 3 m/s^2]\n"
		"meta:\n"
		"  title: \"a \\\"b\\\"\\x0a\"\n");
	free(out);
	dem_scene_free(s);
}

/* The dump loads as a scene that gives exactly the same values (even with
 * other defaults), and dumps to the same text again. */
static void test_dump_round_trip(void **state)
{
	dem_scene_t *s = load("pack:\n  radius:\n    min: 0.1 mm\n    law: lnrd\n"
			      "  n: 12345\n  density: 0.123456789012345678\n"
			      "  aspect: [1.5, 1e-7]\n"
			      "detect:\n  algorithm: brute\n  shape: no\n"
			      "  periodic: 'null'\n"
			      "shot:\n  speed: 1 mm/us\n  angle: 33.3 deg\n"
			      "material:\n  rho: 7.85 g/cm^3\n"
			      "  visc: 1e-3 m^-1 kg s^-1\n"
			      "run:\n  gravity: [0, 0, -9.81 m/s^2]\n"
			      "meta:\n  title: \" lead: 'x' #1 \\t\"\n");
	struct values a, b;
	char *first, *second;
	dem_scene_t *t;

	(void)state;
	read_values(s, &a, 1);
	first = dump_to_string(s);
	write_file("dump.yaml", first);
	{
		dem_error_t e = { 0, "" };

		assert_int_equal(dem_scene_load(&t, "dump.yaml", &e), 0);
		read_values(t, &b, 2);
		assert_int_equal(dem_scene_check(t, (const char *const[]){
				"pack", "detect", "shot", "material", "run",
				"meta", NULL }, &e), 0);
	}
	assert_same_values(&a, &b);
	assert_string_equal(a.periodic, "null");
	assert_string_equal(a.title, " lead: 'x' #1 \t");
	second = dump_to_string(t);
	assert_string_equal(first, second);
	free(first);
	free(second);
	dem_scene_free(t);
	dem_scene_free(s);
}

/* Numbers are printed in the shortest form that reads back exactly. */
static void test_dump_numbers(void **state)
{
	static const double vals[] = {
		0.1, 0.0007, 1.0 / 3, 2.0 / 3, 1e-300, 5e-324, 1.7976931348623157e308,
		123456789012345678.0, 0.30000000000000004, -0.0,
	};
	static const char *const want[] = {
		"0.1", "0.0007", "0.3333333333333333", "0.6666666666666666",
		"1e-300", "4.94065645841247e-324", "1.7976931348623157e+308",
		"1.2345678901234568e+17", "0.30000000000000004", "-0",
	};
	size_t i;

	(void)state;
	for (i = 0; i < sizeof vals / sizeof vals[0]; i++) {
		dem_scene_t *s;
		dem_error_t e = { 0, "" };
		char *out, line[80];
		double v;

		assert_int_equal(dem_scene_load(&s, NULL, &e), 0);
		assert_int_equal(dem_scene_quantity(s, "run.x", DEM_DIM_NONE,
						    vals[i], -HUGE_VAL,
						    HUGE_VAL, &v, &e), 0);
		out = dump_to_string(s);
		snprintf(line, sizeof line, "run:\n  x: %s\n", want[i]);
		assert_string_equal(out, line);
		free(out);
		dem_scene_free(s);
	}
}

/* Nothing is dumped for a key without a default (NAN, NULL) that the
 * scene does not set; an empty scene dumps as nothing, and a key that is
 * a value and a group keeps the first. */
static void test_dump_edges(void **state)
{
	dem_scene_t *s;
	dem_error_t e = { 0, "" };
	const char *str;
	double v, w[2] = { 5, 5 };
	long n;
	char *out;

	(void)state;
	assert_int_equal(dem_scene_load(&s, NULL, &e), 0);
	out = dump_to_string(s);
	assert_string_equal(out, "");
	free(out);
	assert_int_equal(dem_scene_quantity(s, "run.t", DEM_DIM_TIME, NAN,
					    0, HUGE_VAL, &v, &e), 0);
	assert_true(isnan(v));
	assert_int_equal(dem_scene_string(s, "run.name", NULL, &str, &e), 0);
	assert_int_equal(dem_scene_vector(s, "run.v", DEM_DIM_NONE, 2, NULL, 0,
					  1, w, &e), 0);
	assert_int_equal(dem_scene_choice(s, "run.algo", algos, -1,
					  (int *)&n, &e), 0);
	assert_int_equal(dem_scene_int(s, "run.a", 1, 0, 9, &n, &e), 0);
	assert_int_equal(dem_scene_int(s, "run.a.b", 2, 0, 9, &n, &e), 0);
	out = dump_to_string(s);
	assert_string_equal(out, "run:\n  a: 1\n");
	free(out);
	dem_scene_free(s);
}

/* No fixed maxima: a mapping of 3000 keys loads, reads and checks. */
static void test_many_keys(void **state)
{
	const size_t nkeys = 3000;
	char *text = malloc(nkeys * 32 + 16), key[64];
	dem_error_t e = { 0, "" };
	dem_scene_t *s;
	size_t i, k;
	long n;

	(void)state;
	assert_non_null(text);
	k = (size_t)sprintf(text, "run:\n");
	for (i = 0; i < nkeys; i++)
		k += (size_t)sprintf(text + k, "  k%zu: %zu\n", i, i);
	s = load(text);
	for (i = 0; i < nkeys; i++) {
		snprintf(key, sizeof key, "run.k%zu", i);
		assert_int_equal(dem_scene_int(s, key, -1, 0, LONG_MAX, &n, &e),
				 0);
		assert_int_equal(n, (long)i);
	}
	assert_int_equal(dem_scene_check(s, (const char *const[]){ "run",
				NULL }, &e), 0);
	free(text);
	dem_scene_free(s);
}

/* ---- library files (use:) ------------------------------------------------ */

/* A data directory of the test's own, so that no test depends on the
 * toolkit's real library files: DEM_DATA=<tmp>/share, with materials/ and
 * shots/.  Returns the folder. */
static const char *use_share(void)
{
	static char share[4200];
	char cwd[4096];

	assert_non_null(getcwd(cwd, sizeof cwd));
	snprintf(share, sizeof share, "%s/share", cwd);
	assert_true(mkdir("share", 0777) == 0 || errno == EEXIST);
	assert_true(mkdir("share/materials", 0777) == 0 || errno == EEXIST);
	assert_true(mkdir("share/shots", 0777) == 0 || errno == EEXIST);
	assert_int_equal(setenv("DEM_DATA", share, 1), 0);
	return share;
}

/* Text of a material library: line numbers matter to the tests below. */
static const char al_yaml[] =
	"# a made-up aluminium, for the tests\n"        /* 1 */
	"E: 72 GPa\n"                                   /* 2 */
	"nu: 0.33\n"                                    /* 3 */
	"rho: 2700 kg/m^3\n"                            /* 4 */
	"law: johnson-cook\n"                           /* 5 */
	"johnson-cook:\n"                               /* 6 */
	"  A: 300 MPa\n"                                /* 7 */
	"  B: 400 MPa\n"                                /* 8 */
	"  n: 0.3\n"                                    /* 9 */
	"table: [1, 2, 3]\n"                            /* 10 */
	"rate: {law: cowper-symonds, C: 6500 1/s}\n";   /* 11 */

/* Keys the scene gives win; mappings merge key by key, at any depth;
 * sequences and scalars are replaced whole.  Reference: the merge rule of
 * dem-scene(5), "Library files". */
static void test_use_merge(void **state)
{
	dem_error_t e = { 0, "" };
	dem_scene_t *s;
	const char *law;
	double v;

	(void)state;
	use_share();
	write_file("share/materials/al.yaml", al_yaml);
	s = load("material:\n"
		 "  use: al\n"
		 "  nu: 0.3\n"
		 "  table: [4, 5]\n"
		 "  johnson-cook:\n"
		 "    B: 500 MPa\n"
		 "    T: 400 K\n"
		 "  rate: 1\n");
	/* from the library */
	assert_int_equal(dem_scene_quantity(s, "material.E", DEM_DIM_PRESSURE,
					    NAN, 0, HUGE_VAL, &v, &e), 0);
	assert_true(v == 72e9);
	assert_int_equal(dem_scene_string(s, "material.law", NULL, &law, &e),
			 0);
	assert_string_equal(law, "johnson-cook");
	/* the scene's scalar wins */
	assert_int_equal(dem_scene_quantity(s, "material.nu", DEM_DIM_NONE,
					    NAN, 0, 0.5, &v, &e), 0);
	assert_true(v == 0.3);
	/* deep merge: A from the library, B replaced, T added */
	assert_int_equal(dem_scene_quantity(s, "material.johnson-cook.A",
					    DEM_DIM_PRESSURE, NAN, 0, HUGE_VAL,
					    &v, &e), 0);
	assert_true(v == 300e6);
	assert_int_equal(dem_scene_quantity(s, "material.johnson-cook.B",
					    DEM_DIM_PRESSURE, NAN, 0, HUGE_VAL,
					    &v, &e), 0);
	assert_true(v == 500e6);
	assert_int_equal(dem_scene_quantity(s, "material.johnson-cook.T",
					    DEM_DIM_TEMPERATURE, NAN, 0,
					    HUGE_VAL, &v, &e), 0);
	assert_true(v == 400);
	assert_int_equal(dem_scene_quantity(s, "material.johnson-cook.n",
					    DEM_DIM_NONE, NAN, 0, 1, &v, &e),
			 0);
	assert_true(v == 0.3);
	/* a sequence is replaced, not appended to */
	assert_int_equal(dem_scene_length(s, "material.table"), 2);
	/* a scalar of the scene replaces a mapping of the library whole */
	assert_false(dem_scene_has(s, "material.rate.law"));
	assert_int_equal(dem_scene_length(s, "material.rate"), 1);
	dem_scene_free(s);
}

/* A value that came from a library file is reported at its own file,
 * line and column; the scene's values at the scene's. */
static void test_use_positions(void **state)
{
	char want[8192], lib[4300];
	dem_error_t e = { 0, "" };
	const char *share = use_share();
	dem_scene_t *s;
	double v;

	(void)state;
	write_file("share/materials/bad.yaml",
		   "E: 72 GPa\n"
		   "rho: 2700 m\n"
		   "johnson-cook:\n"
		   "  A: fast\n");
	s = load("material:\n  use: bad\n  nu: 2\n");
	assert_int_equal(dem_scene_quantity(s, "material.rho", DEM_DIM_DENSITY,
					    NAN, 0, HUGE_VAL, &v, &e),
			 DEM_EINPUT);
	snprintf(want, sizeof want, "%s/materials/bad.yaml:2:6: material.rho: "
		 "unit 'm' is a length, expected a density (e.g. "
		 "'7800 kg/m^3')", share);
	assert_string_equal(e.msg, want);
	dem_error_clear(&e);
	assert_int_equal(dem_scene_quantity(s, "material.johnson-cook.A",
					    DEM_DIM_PRESSURE, NAN, 0, HUGE_VAL,
					    &v, &e), DEM_EINPUT);
	snprintf(want, sizeof want, "%s/materials/bad.yaml:4:6: "
		 "material.johnson-cook.A: expected a pressure (e.g. "
		 "'72 GPa'), got 'fast' (not a number)", share);
	assert_string_equal(e.msg, want);
	dem_error_clear(&e);
	/* a problem the program finds after reading points there too */
	assert_int_equal(dem_scene_error(s, "material.E", &e, "too stiff"),
			 DEM_EINPUT);
	snprintf(want, sizeof want, "%s/materials/bad.yaml:1:4: material.E: "
		 "too stiff", share);
	assert_string_equal(e.msg, want);
	dem_error_clear(&e);
	/* the scene's own value still names the scene */
	assert_int_equal(dem_scene_quantity(s, "material.nu", DEM_DIM_NONE,
					    NAN, 0, 0.5, &v, &e), DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:3:7: material.nu: 2 is out of "
			    "range, expected a number in [0, 0.5]");
	dem_error_clear(&e);
	dem_scene_free(s);

	/* a syntax error in the library names the library */
	write_file("share/materials/broken.yaml", "E: 72 GPa\n  nu: [\n");
	snprintf(lib, sizeof lib, "%s/materials/broken.yaml:2:", share);
	write_file("strip.yaml", "material:\n  use: broken\n");
	s = (dem_scene_t *)&e;
	assert_int_equal(dem_scene_load(&s, "strip.yaml", &e), DEM_EINPUT);
	assert_null(s);
	if (strncmp(e.msg, lib, strlen(lib)) != 0)
		fail_msg("'%s' does not start with '%s'", e.msg, lib);

	/* so does a library that is not a mapping */
	write_file("share/materials/list.yaml", "- E\n- nu\n");
	snprintf(want, sizeof want, "%s/materials/list.yaml:1:1: a library "
		 "file is a mapping of a section's settings (E:, nu:, ...), "
		 "got a sequence", share);
	load_fails("material:\n  use: list\n", DEM_EINPUT, want);
}

/* An unknown library name is an error at the value of use:, naming the
 * folder searched and why that one; so are names that cannot be one. */
static void test_use_unknown(void **state)
{
	const char *share = use_share();
	char want[8192];
	dem_error_t e = { 0, "" };
	dem_scene_t *s = (dem_scene_t *)&e;

	(void)state;
	snprintf(want, sizeof want, "strip.yaml:2:8: material.use: unknown "
		 "library 'al9999': no al9999.yaml in %s/materials (from "
		 "DEM_DATA)", share);
	load_fails("material:\n  use: al9999\n", DEM_EINPUT, want);
	snprintf(want, sizeof want, "strip.yaml:2:8: shot.use: unknown "
		 "library 'S230': no S230.yaml in %s/shots (from DEM_DATA)",
		 share);
	load_fails("shot:\n  use: S230\n", DEM_EINPUT, want);
	load_fails("material:\n  use: a b\n", DEM_EINPUT,
		   "strip.yaml:2:8: material.use: expected a library name "
		   "(e.g. 'al7075') or a path to a .yaml file, got 'a b'");
	load_fails("material:\n  use: .hidden\n", DEM_EINPUT,
		   "strip.yaml:2:8: material.use: expected a library name "
		   "(e.g. 'al7075') or a path to a .yaml file, got '.hidden'");
	load_fails("material:\n  use:\n", DEM_EINPUT,
		   "strip.yaml:2:7: material.use: expected a library name "
		   "(e.g. 'al7075') or a path to a .yaml file, got an empty "
		   "value");
	load_fails("material:\n  use: [al, steel]\n", DEM_EINPUT,
		   "strip.yaml:2:8: material.use: expected a library name "
		   "(e.g. 'al7075') or a path to a .yaml file, got a sequence");
	/* a path is relative to the scene's folder */
	load_fails("material:\n  use: ../al.yaml\n", DEM_EINPUT,
		   "strip.yaml:2:8: material.use: cannot read '../al.yaml': "
		   "No such file or directory");

	/* without DEM_DATA the folder is found from the program, or is the
	 * compiled-in one; either way the message says where it looked */
	assert_int_equal(unsetenv("DEM_DATA"), 0);
	write_file("strip.yaml", "material:\n  use: no-such-library-x\n");
	assert_int_equal(dem_scene_load(&s, "strip.yaml", &e), DEM_EINPUT);
	assert_null(s);
	assert_non_null(strstr(e.msg, "strip.yaml:2:8: material.use: unknown "
			       "library 'no-such-library-x': no "
			       "no-such-library-x.yaml in /"));
	assert_non_null(strstr(e.msg, "/materials ("));
}

/* use: is for the sections that have a library folder; others refuse it
 * at the key.  The shot section takes one from shots/. */
static void test_use_sections(void **state)
{
	dem_error_t e = { 0, "" };
	dem_scene_t *s;
	double v;

	(void)state;
	use_share();
	write_file("share/shots/s230.yaml", "radius: 0.3 mm\n"
		   "density: 7800 kg/m^3\n");
	load_fails("pack:\n  n: 5\n  use: al\n", DEM_EINPUT,
		   "strip.yaml:3:3: pack.use: only the sections material and "
		   "shot take a library file (use:)");
	load_fails("detect: {use: al}\n", DEM_EINPUT,
		   "strip.yaml:1:10: detect.use: only the sections material "
		   "and shot take a library file (use:)");
	s = load("shot:\n  use: s230\n  speed: 50 m/s\n");
	assert_int_equal(dem_scene_quantity(s, "shot.radius", DEM_DIM_LENGTH,
					    NAN, 0, HUGE_VAL, &v, &e), 0);
	assert_true(v == 0.0003);
	assert_int_equal(dem_scene_quantity(s, "shot.density",
					    DEM_DIM_DENSITY, NAN, 0, HUGE_VAL,
					    &v, &e), 0);
	assert_true(v == 7800);
	dem_scene_free(s);
	/* a use: deeper than a section is no library: an unknown key */
	s = load("material:\n  rate:\n    use: al\n");
	assert_int_equal(dem_scene_quantity(s, "material.rate.C", DEM_DIM_RATE,
					    1, 0, HUGE_VAL, &v, &e), 0);
	assert_int_equal(dem_scene_check(s, (const char *const[]){ "material",
					 NULL }, &e), DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:3:5: unknown key "
			    "'material.rate.use'; known keys here: C");
	dem_scene_free(s);
}

/* A library file cannot use another: refused at its own position. */
static void test_use_in_library(void **state)
{
	const char *share = use_share();
	char want[8192];

	(void)state;
	write_file("share/materials/al.yaml", al_yaml);
	write_file("share/materials/chain.yaml", "E: 1 GPa\nuse: al\n");
	snprintf(want, sizeof want, "%s/materials/chain.yaml:2:1: "
		 "material.use: a library file cannot use another (use: is for "
		 "scenes)", share);
	load_fails("material:\n  use: chain\n", DEM_EINPUT, want);
}

/* A name with a '/' or ending in .yaml is a file relative to the scene's
 * folder, and messages name it as found from there. */
static void test_use_path(void **state)
{
	char abs[4200], text[4300], cwd[4096];
	dem_error_t e = { 0, "" };
	dem_scene_t *s = NULL;
	double v;

	(void)state;
	use_share();
	assert_true(mkdir("sub", 0777) == 0 || errno == EEXIST);
	write_file("sub/mine.yaml", "E: 70 GPa\nnu: 3 m\n");
	write_file("sub/strip.yaml", "material:\n  use: mine.yaml\n");
	assert_int_equal(dem_scene_load(&s, "sub/strip.yaml", &e), 0);
	assert_int_equal(dem_scene_quantity(s, "material.E", DEM_DIM_PRESSURE,
					    NAN, 0, HUGE_VAL, &v, &e), 0);
	assert_true(v == 70e9);
	assert_int_equal(dem_scene_quantity(s, "material.nu", DEM_DIM_NONE,
					    NAN, 0, 0.5, &v, &e), DEM_EINPUT);
	assert_string_equal(e.msg, "sub/mine.yaml:2:5: material.nu: unit 'm' "
			    "is a length, expected a number (e.g. '0.5')");
	dem_scene_free(s);
	/* an absolute path is taken as it is */
	assert_non_null(getcwd(cwd, sizeof cwd));
	snprintf(abs, sizeof abs, "%s/sub/mine.yaml", cwd);
	snprintf(text, sizeof text, "material:\n  use: %s\n", abs);
	s = load(text);
	assert_int_equal(dem_scene_quantity(s, "material.E", DEM_DIM_PRESSURE,
					    NAN, 0, HUGE_VAL, &v, &e), 0);
	assert_true(v == 70e9);
	dem_scene_free(s);
}

/* --dump-scene shows the use: line first in its section (with the file
 * found, as a comment) and the values resolved from the library; the dump
 * loads again to the same values.  dem_scene_check knows use:, passes over
 * library keys the program did not read, and still catches the scene's
 * own typos. */
static void test_use_dump_check(void **state)
{
	static const char *const material[] = { "material", NULL };
	const char *share = use_share();
	char want[8192], *out, *again;
	dem_error_t e = { 0, "" };
	dem_scene_t *s;
	double v[3];

	(void)state;
	write_file("share/materials/al.yaml", al_yaml);
	s = load("material:\n  use: al\n  nu: 0.3\n"
		 "  johnson-cook: {T: 500 K}\n");
	assert_int_equal(dem_scene_quantity(s, "material.E", DEM_DIM_PRESSURE,
					    NAN, 0, HUGE_VAL, &v[0], &e), 0);
	assert_int_equal(dem_scene_quantity(s, "material.nu", DEM_DIM_NONE,
					    NAN, 0, 0.5, &v[1], &e), 0);
	assert_int_equal(dem_scene_quantity(s, "material.johnson-cook.T",
					    DEM_DIM_TEMPERATURE, 293, 0,
					    HUGE_VAL, &v[2], &e), 0);
	assert_int_equal(dem_scene_check(s, material, &e), 0);
	out = dump_to_string(s);
	snprintf(want, sizeof want,
		 "material:\n"
		 "  use: al  # %s/materials/al.yaml\n"
		 "  E: 72000000000 Pa\n"
		 "  nu: 0.3\n"
		 "  johnson-cook:\n"
		 "    T: 500 K\n", share);
	assert_string_equal(out, want);
	dem_scene_free(s);

	/* the dump is a scene: the same values, the same dump */
	s = load(out);
	assert_int_equal(dem_scene_quantity(s, "material.E", DEM_DIM_PRESSURE,
					    NAN, 0, HUGE_VAL, &v[0], &e), 0);
	assert_int_equal(dem_scene_quantity(s, "material.nu", DEM_DIM_NONE,
					    NAN, 0, 0.5, &v[1], &e), 0);
	assert_int_equal(dem_scene_quantity(s, "material.johnson-cook.T",
					    DEM_DIM_TEMPERATURE, 293, 0,
					    HUGE_VAL, &v[2], &e), 0);
	assert_true(v[0] == 72e9 && v[1] == 0.3 && v[2] == 500);
	again = dump_to_string(s);
	assert_string_equal(again, out);
	free(again);
	free(out);
	dem_scene_free(s);

	/* use: is known even where the program read nothing of the section */
	s = load("material:\n  use: al\n");
	assert_int_equal(dem_scene_check(s, material, &e), 0);
	dem_scene_free(s);

	/* a typo of the scene is caught beside a library */
	s = load("material:\n  use: al\n  Ee: 70 GPa\n");
	assert_int_equal(dem_scene_quantity(s, "material.E", DEM_DIM_PRESSURE,
					    NAN, 0, HUGE_VAL, &v[0], &e), 0);
	assert_int_equal(dem_scene_check(s, material, &e), DEM_EINPUT);
	assert_string_equal(e.msg, "strip.yaml:3:3: unknown key 'material.Ee'; "
			    "known keys here: E, use");
	dem_scene_free(s);
}

/* A command-line option overrides a value that came from a library, at
 * any depth; its errors name the option.  use: itself cannot be set from
 * the command line. */
static void test_use_override(void **state)
{
	dem_error_t e = { 0, "" };
	dem_scene_t *s;
	double v;

	(void)state;
	use_share();
	write_file("share/materials/al.yaml", al_yaml);
	s = load("material:\n  use: al\n");
	assert_int_equal(dem_scene_override(s, "material.E", "70 GPa", "--E",
					    &e), 0);
	assert_int_equal(dem_scene_override(s, "material.johnson-cook.A",
					    "310 MPa", "--jc-A", &e), 0);
	assert_int_equal(dem_scene_quantity(s, "material.E", DEM_DIM_PRESSURE,
					    NAN, 0, HUGE_VAL, &v, &e), 0);
	assert_true(v == 70e9);
	assert_int_equal(dem_scene_quantity(s, "material.johnson-cook.A",
					    DEM_DIM_PRESSURE, NAN, 0, HUGE_VAL,
					    &v, &e), 0);
	assert_true(v == 310e6);
	/* the library's neighbours of the overridden key stay */
	assert_int_equal(dem_scene_quantity(s, "material.johnson-cook.B",
					    DEM_DIM_PRESSURE, NAN, 0, HUGE_VAL,
					    &v, &e), 0);
	assert_true(v == 400e6);
	assert_int_equal(dem_scene_override(s, "material.rho", "2 m", "--rho",
					    &e), 0);
	assert_int_equal(dem_scene_quantity(s, "material.rho",
					    DEM_DIM_DENSITY, NAN, 0, HUGE_VAL,
					    &v, &e), DEM_EUSAGE);
	assert_string_equal(e.msg, "command line: --rho: material.rho: unit "
			    "'m' is a length, expected a density (e.g. "
			    "'7800 kg/m^3')");
	dem_error_clear(&e);
	assert_int_equal(dem_scene_override(s, "material.use", "steel",
					    "--use", &e), DEM_EUSAGE);
	assert_string_equal(e.msg, "command line: --use: material.use cannot "
			    "be set on the command line; write it in the "
			    "scene");
	dem_scene_free(s);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_null_path_defaults),
		cmocka_unit_test(test_empty_files),
		cmocka_unit_test(test_unreadable),
		cmocka_unit_test(test_syntax_errors),
		cmocka_unit_test(test_bad_utf8),
		cmocka_unit_test(test_top_not_mapping),
		cmocka_unit_test(test_duplicate_keys),
		cmocka_unit_test(test_refused_yaml),
		cmocka_unit_test(test_quantity),
		cmocka_unit_test(test_quantity_errors),
		cmocka_unit_test(test_quantity_types),
		cmocka_unit_test(test_quantity_range),
		cmocka_unit_test(test_int),
		cmocka_unit_test(test_bool),
		cmocka_unit_test(test_choice),
		cmocka_unit_test(test_vector),
		cmocka_unit_test(test_vector_scalar),
		cmocka_unit_test(test_string),
		cmocka_unit_test(test_scene_error),
		cmocka_unit_test(test_override),
		cmocka_unit_test(test_override_errors),
		cmocka_unit_test(test_check_unknown_key),
		cmocka_unit_test(test_check_sections),
		cmocka_unit_test(test_check_override),
		cmocka_unit_test(test_dump_format),
		cmocka_unit_test(test_dump_round_trip),
		cmocka_unit_test(test_dump_numbers),
		cmocka_unit_test(test_dump_edges),
		cmocka_unit_test(test_many_keys),
		cmocka_unit_test(test_use_merge),
		cmocka_unit_test(test_use_positions),
		cmocka_unit_test(test_use_unknown),
		cmocka_unit_test(test_use_sections),
		cmocka_unit_test(test_use_in_library),
		cmocka_unit_test(test_use_path),
		cmocka_unit_test(test_use_dump_check),
		cmocka_unit_test(test_use_override),
	};

	return cmocka_run_group_tests(tests, group_setup, group_teardown);
}
