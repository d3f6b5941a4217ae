/* test_units.c - unit tests of lib/core/units.c: quantities with units to SI.
 *
 * Reference: the SI brochure (prefixes, derived units).  Values are compared
 * exactly: a power-of-ten unit must give the double nearest to the decimal
 * value ("0.7 mm" == 0.0007), because units.c folds prefixes into the decimal
 * exponent instead of multiplying.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/units.h"

#define PI 3.14159265358979323846
#define DEG (PI / 180)

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

/* Macros like the header's, not const objects: a const object is not a
 * constant expression in C, and clang refuses it in the tables below. */
#define AREA ((dem_dim_t){ 2, 0, 0, 0, 0 })
#define VOLUME ((dem_dim_t){ 3, 0, 0, 0, 0 })
#define PA_PER_K ((dem_dim_t){ -1, 1, -2, 0, -1 })
#define PER_K ((dem_dim_t){ 0, 0, 0, 0, -1 })
#define K_PER_S ((dem_dim_t){ 0, 0, -1, 0, 1 })

struct accept {
	const char *text;
	dem_dim_t dim;
	double si;
};

/* Every accepted spelling, with the exact SI value expected. */
static const struct accept accepted[] = {
	/* bare numbers are SI of the expected dimension */
	{ "0.25", DEM_DIM_LENGTH, 0.25 },
	{ "  3  ", DEM_DIM_LENGTH, 3 },
	{ "-3", DEM_DIM_NONE, -3 },
	{ "+2", DEM_DIM_NONE, 2 },
	{ ".5", DEM_DIM_NONE, 0.5 },
	{ "5.", DEM_DIM_NONE, 5 },
	{ "1e3", DEM_DIM_NONE, 1000 },
	{ "1E-3", DEM_DIM_NONE, 0.001 },
	{ "30", DEM_DIM_ANGLE, 30 },
	/* lengths: every prefix, and three spellings of micro */
	{ "1 m", DEM_DIM_LENGTH, 1 },
	{ "0.7 mm", DEM_DIM_LENGTH, 0.0007 },
	{ "0.7mm", DEM_DIM_LENGTH, 0.0007 },
	{ "2 cm", DEM_DIM_LENGTH, 0.02 },
	{ "1 km", DEM_DIM_LENGTH, 1000 },
	{ "5 um", DEM_DIM_LENGTH, 5e-6 },
	{ "5 \xc2\xb5m", DEM_DIM_LENGTH, 5e-6 },
	{ "5 \xce\xbcm", DEM_DIM_LENGTH, 5e-6 },
	{ "3 nm", DEM_DIM_LENGTH, 3e-9 },
	{ "1e3 nm", DEM_DIM_LENGTH, 1e-6 },
	{ "1E3 mm", DEM_DIM_LENGTH, 1 },
	{ "-3 mm", DEM_DIM_LENGTH, -0.003 },
	{ "1 Mm", DEM_DIM_LENGTH, 1e6 },
	{ "1 Gm", DEM_DIM_LENGTH, 1e9 },
	/* times */
	{ "2 s", DEM_DIM_TIME, 2 },
	{ "3 ms", DEM_DIM_TIME, 0.003 },
	{ "5 us", DEM_DIM_TIME, 5e-6 },
	{ "5 \xc2\xb5s", DEM_DIM_TIME, 5e-6 },
	{ "2 ns", DEM_DIM_TIME, 2e-9 },
	/* masses: the gram is 1e-3 kg */
	{ "1 kg", DEM_DIM_MASS, 1 },
	{ "0.5 g", DEM_DIM_MASS, 0.0005 },
	{ "3 mg", DEM_DIM_MASS, 3e-6 },
	{ "1 Mg", DEM_DIM_MASS, 1000 },
	/* forces and pressures */
	{ "10 N", DEM_DIM_FORCE, 10 },
	{ "2 kN", DEM_DIM_FORCE, 2000 },
	{ "3 mN", DEM_DIM_FORCE, 0.003 },
	{ "1 kg m/s^2", DEM_DIM_FORCE, 1 },
	{ "1 kg*m*s^-2", DEM_DIM_FORCE, 1 },
	{ "5 Pa", DEM_DIM_PRESSURE, 5 },
	{ "1 kPa", DEM_DIM_PRESSURE, 1000 },
	{ "350 MPa", DEM_DIM_PRESSURE, 350e6 },
	{ "72 GPa", DEM_DIM_PRESSURE, 72e9 },
	{ "200 N/mm^2", DEM_DIM_PRESSURE, 200e6 },
	{ "1 N m^-2", DEM_DIM_PRESSURE, 1 },
	/* densities */
	{ "7800 kg/m^3", DEM_DIM_DENSITY, 7800 },
	{ "7800 kg / m^3", DEM_DIM_DENSITY, 7800 },
	{ "7800 kg m^-3", DEM_DIM_DENSITY, 7800 },
	{ "7.8 g/cm^3", DEM_DIM_DENSITY, 7800 },
	/* velocities, accelerations, rates */
	{ "46.5 m/s", DEM_DIM_VELOCITY, 46.5 },
	{ "46.5 m s^-1", DEM_DIM_VELOCITY, 46.5 },
	{ "1 mm/ms", DEM_DIM_VELOCITY, 1 },
	{ "9.81 m/s^2", DEM_DIM_ACCEL, 9.81 },
	{ "9.81 m/s/s", DEM_DIM_ACCEL, 9.81 },
	{ "100 1/s", DEM_DIM_RATE, 100 },
	{ "100 1 / s", DEM_DIM_RATE, 100 },
	{ "100 s^-1", DEM_DIM_RATE, 100 },
	{ "1 1/ms", DEM_DIM_RATE, 1000 },
	/* areas and volumes: the prefix is raised with the unit */
	{ "1 mm^2", AREA, 1e-6 },
	{ "2 cm^3", VOLUME, 2e-6 },
	{ "1 m^+3", VOLUME, 1 },
	/* angles, in radians */
	{ "1 rad", DEM_DIM_ANGLE, 1 },
	{ "2 mrad", DEM_DIM_ANGLE, 0.002 },
	{ "30 deg", DEM_DIM_ANGLE, 30 * DEG },
	{ "180 deg", DEM_DIM_ANGLE, 180 * DEG },
	{ "-45 deg", DEM_DIM_ANGLE, -45 * DEG },
	/* temperatures, in kelvin; prefixes apply as to any SI unit */
	{ "293 K", DEM_DIM_TEMPERATURE, 293 },
	{ "293", DEM_DIM_TEMPERATURE, 293 },
	{ "1.5 kK", DEM_DIM_TEMPERATURE, 1500 },
	{ "20 mK", DEM_DIM_TEMPERATURE, 0.02 },
	{ "1775K", DEM_DIM_TEMPERATURE, 1775 },
	/* a temperature inside a compound unit */
	{ "2 MPa/K", PA_PER_K, 2e6 },
	{ "1e-5 1/K", PER_K, 1e-5 },
	{ "10 K/s", K_PER_S, 10 },
	/* a dimensionless ratio written with cancelling units */
	{ "5 mm/m", DEM_DIM_NONE, 0.005 },
	/* underflow is a (tiny) finite value, not an error */
	{ "1e-400", DEM_DIM_NONE, 0 },
};

/* Each accepted spelling converts to exactly the SI value in the table. */
static void test_accepted(void **state)
{
	size_t i;

	(void)state;
	for (i = 0; i < COUNT(accepted); i++) {
		char why[256] = "";
		double v = -12345;
		int rc = dem_units_parse(accepted[i].text, accepted[i].dim,
					 &v, why, sizeof why);

		if (rc != 0 || v != accepted[i].si)
			fail_msg("'%s': rc %d, %.17g (want %.17g): %s",
				 accepted[i].text, rc, v, accepted[i].si, why);
	}
}

struct reject {
	const char *text;
	dem_dim_t dim;
	const char *why;        /* a substring of the reason */
};

/* Every rejection, with the reason it must give. */
static const struct reject rejected[] = {
	/* wrong dimension, named in words */
	{ "5 s", DEM_DIM_LENGTH, "unit 's' is a time, expected a length" },
	{ "1 mm", DEM_DIM_VELOCITY,
	  "unit 'mm' is a length, expected a velocity" },
	{ "5 m^2", DEM_DIM_LENGTH, "unit 'm^2' is an area, expected a length" },
	{ "1 GPa", DEM_DIM_DENSITY,
	  "unit 'GPa' is a pressure, expected a density" },
	{ "9.81 m/s^2", DEM_DIM_VELOCITY,
	  "unit 'm/s^2' is an acceleration, expected a velocity" },
	{ "30 deg", DEM_DIM_NONE, "unit 'deg' is an angle, expected a number" },
	{ "3 kg", DEM_DIM_FORCE, "unit 'kg' is a mass, expected a force" },
	{ "3 m", DEM_DIM_RATE, "unit 'm' is a length, expected a rate" },
	{ "293 m", DEM_DIM_TEMPERATURE,
	  "unit 'm' is a length, expected a temperature" },
	{ "293 K", DEM_DIM_NONE,
	  "unit 'K' is a temperature, expected a number" },
	{ "293 K", DEM_DIM_TIME, "unit 'K' is a temperature, expected a time" },
	{ "2 MPa", PA_PER_K,
	  "unit 'MPa' is a pressure, expected a quantity in m^-1 kg s^-2 K^-1" },
	/* wrong dimension without a name: the SI form */
	{ "1 m^-1 s^-1", DEM_DIM_NONE,
	  "unit 'm^-1 s^-1' is a quantity in m^-1 s^-1, expected a number" },
	{ "1 m", (dem_dim_t){ 1, 2, 0, 0, 0 },
	  "unit 'm' is a length, expected a quantity in m kg^2" },
	/* unknown units, named */
	{ "5 mmm", DEM_DIM_LENGTH, "unknown unit 'mmm'" },
	{ "5 min", DEM_DIM_TIME, "unknown unit 'min'" },
	{ "5 h", DEM_DIM_TIME, "unknown unit 'h'" },
	{ "5 Hz", DEM_DIM_RATE, "unknown unit 'Hz'" },
	{ "5 mdeg", DEM_DIM_ANGLE, "unknown unit 'mdeg'" },
	{ "5 kkg", DEM_DIM_MASS, "unknown unit 'kkg'" },
	{ "5 dm", DEM_DIM_LENGTH, "unknown unit 'dm'" },
	{ "5 M", DEM_DIM_LENGTH, "unknown unit 'M'" },
	{ "5 in", DEM_DIM_LENGTH, "unknown unit 'in'" },
	{ "5 kg/mx^3", DEM_DIM_DENSITY, "unknown unit 'mx'" },
	{ "0x10", DEM_DIM_NONE, "unknown unit 'x'" },
	{ "5 k", DEM_DIM_TEMPERATURE, "unknown unit 'k'" },
	{ "5 Kelvin", DEM_DIM_TEMPERATURE, "unknown unit 'Kelvin'" },
	/* offset scales are refused, with the kelvin hint */
	{ "20 degC", DEM_DIM_TEMPERATURE, "unknown unit 'degC' (temperatures "
	  "are absolute, in kelvin: '293 K')" },
	{ "20 \xc2\xb0" "C", DEM_DIM_TEMPERATURE, "unknown unit '\xc2\xb0" "C' "
	  "(temperatures are absolute" },
	{ "68 degF", DEM_DIM_TEMPERATURE, "unknown unit 'degF' (temperatures" },
	{ "20 C", DEM_DIM_TEMPERATURE, "unknown unit 'C' (temperatures" },
	{ "20 deg C", DEM_DIM_TEMPERATURE, "unknown unit 'C' (temperatures" },
	{ "5 kdegC", DEM_DIM_TEMPERATURE, "unknown unit 'kdegC'" },
	/* not a number */
	{ "", DEM_DIM_NONE, "not a number" },
	{ "   ", DEM_DIM_NONE, "not a number" },
	{ "fast", DEM_DIM_VELOCITY, "not a number" },
	{ "mm", DEM_DIM_LENGTH, "not a number" },
	{ "-", DEM_DIM_NONE, "not a number" },
	{ ".", DEM_DIM_NONE, "not a number" },
	{ "e5", DEM_DIM_NONE, "not a number" },
	{ "information", DEM_DIM_NONE, "not a number" },
	/* NaN and infinities, however spelled */
	{ "nan", DEM_DIM_NONE, "not finite" },
	{ "NaN", DEM_DIM_LENGTH, "not finite" },
	{ "inf", DEM_DIM_NONE, "not finite" },
	{ "-inf", DEM_DIM_NONE, "not finite" },
	{ "Infinity", DEM_DIM_NONE, "not finite" },
	{ ".inf", DEM_DIM_NONE, "not finite" },
	{ "-.Inf", DEM_DIM_NONE, "not finite" },
	{ ".nan", DEM_DIM_NONE, "not finite" },
	{ "1e999", DEM_DIM_NONE, "not finite" },
	{ "1e300 GPa", DEM_DIM_PRESSURE, "not finite" },
	{ "1e999999999999999999999", DEM_DIM_NONE, "not finite" },
	/* trailing garbage and malformed expressions */
	{ "1,5", DEM_DIM_NONE, "trailing garbage ',5'" },
	{ "5 mm)", DEM_DIM_LENGTH, "trailing garbage ')'" },
	{ "5 mm;", DEM_DIM_LENGTH, "trailing garbage ';'" },
	{ "51/s", DEM_DIM_RATE, "trailing garbage '/s'" },
	{ "5 /s", DEM_DIM_RATE, "trailing garbage '/s'" },
	{ "5 1", DEM_DIM_NONE, "trailing garbage '1'" },
	{ "1.2.3", DEM_DIM_NONE, "trailing garbage '.3'" },
	{ "5 m^", DEM_DIM_LENGTH, "bad exponent after unit 'm'" },
	{ "5 m^x", DEM_DIM_LENGTH, "bad exponent after unit 'm'" },
	{ "5 m^123", DEM_DIM_LENGTH, "bad exponent after unit 'm'" },
	{ "5 m*", DEM_DIM_LENGTH, "expected a unit at the end" },
	{ "5 m//s", DEM_DIM_VELOCITY, "expected a unit at '/s'" },
	{ "5 m^99 m^99", DEM_DIM_LENGTH, "unit exponent too large" },
};

/* Each rejection fails with -1, leaves the value alone and gives the
 * reason. */
static void test_rejected(void **state)
{
	size_t i;

	(void)state;
	for (i = 0; i < COUNT(rejected); i++) {
		char why[256] = "";
		double v = -12345;
		int rc = dem_units_parse(rejected[i].text, rejected[i].dim,
					 &v, why, sizeof why);

		if (rc != -1 || v != -12345 || !strstr(why, rejected[i].why))
			fail_msg("'%s': rc %d, why '%s' (want '%s')",
				 rejected[i].text, rc, why, rejected[i].why);
	}
}

/* A NULL reason buffer of length 0 is allowed, and a long reason is cut
 * to the buffer. */
static void test_why_buffer(void **state)
{
	char why[8];
	double v;

	(void)state;
	assert_int_equal(dem_units_parse("5 s", DEM_DIM_LENGTH, &v, NULL, 0),
			 -1);
	assert_int_equal(dem_units_parse("5 mm", DEM_DIM_LENGTH, &v, NULL, 0),
			 0);
	assert_true(v == 0.005);
	assert_int_equal(dem_units_parse("5 s", DEM_DIM_LENGTH, &v, why,
					 sizeof why), -1);
	assert_string_equal(why, "unit 's");
}

/* A very long number still parses exactly (no fixed buffer). */
static void test_long_number(void **state)
{
	char text[600];
	double v;

	(void)state;
	memset(text, '0', 500);
	text[0] = '1';
	strcpy(text + 500, "e-499 mm");       /* 1 followed by 499 zeros */
	assert_int_equal(dem_units_parse(text, DEM_DIM_LENGTH, &v, NULL, 0), 0);
	assert_true(v == 1e-3);
}

/* dem_dim_si_name gives the named SI units of the header, "" for none,
 * and "?" for a dimension it has no name for. */
static void test_si_names(void **state)
{
	(void)state;
	assert_string_equal(dem_dim_si_name(DEM_DIM_NONE), "");
	assert_string_equal(dem_dim_si_name(DEM_DIM_LENGTH), "m");
	assert_string_equal(dem_dim_si_name(DEM_DIM_MASS), "kg");
	assert_string_equal(dem_dim_si_name(DEM_DIM_TIME), "s");
	assert_string_equal(dem_dim_si_name(DEM_DIM_ANGLE), "rad");
	assert_string_equal(dem_dim_si_name(DEM_DIM_VELOCITY), "m/s");
	assert_string_equal(dem_dim_si_name(DEM_DIM_ACCEL), "m/s^2");
	assert_string_equal(dem_dim_si_name(DEM_DIM_FORCE), "N");
	assert_string_equal(dem_dim_si_name(DEM_DIM_PRESSURE), "Pa");
	assert_string_equal(dem_dim_si_name(DEM_DIM_DENSITY), "kg/m^3");
	assert_string_equal(dem_dim_si_name(DEM_DIM_RATE), "1/s");
	assert_string_equal(dem_dim_si_name(AREA), "m^2");
	assert_string_equal(dem_dim_si_name(DEM_DIM_TEMPERATURE), "K");
	assert_string_equal(dem_dim_si_name(PA_PER_K), "?");
	assert_string_equal(dem_dim_si_name((dem_dim_t){ -1, 0, -1, 0, 0 }), "?");
}

/* dem_dim_format writes the name, or the generic form in L, M, T, A, Th
 * order; every form it writes parses back to its own dimension. */
static void test_format_round_trip(void **state)
{
	static const dem_dim_t dims[] = {
		DEM_DIM_LENGTH, DEM_DIM_MASS, DEM_DIM_TIME, DEM_DIM_ANGLE,
		DEM_DIM_VELOCITY, DEM_DIM_ACCEL, DEM_DIM_FORCE,
		DEM_DIM_PRESSURE, DEM_DIM_DENSITY, DEM_DIM_RATE,
		{ 2, 0, 0, 0, 0 }, { 3, 0, 0, 0, 0 }, { 0, 1, -2, 0, 0 },
		{ 0, 0, -1, 1, 0 }, { -1, 0, -1, 0, 0 }, { 2, 1, -2, 0, 0 },
		{ -1, 1, -1, 0, 0 }, { 0, 0, 0, 2, 0 }, { 1, 0, 0, -1, 0 },
		DEM_DIM_TEMPERATURE, { -1, 1, -2, 0, -1 }, { 0, 0, 0, 0, -1 },
		{ 0, 0, -1, 0, 1 }, { 0, 0, 0, 0, 2 }, { 0, 0, 0, 1, -1 },
	};
	char unit[64], text[100], why[256];
	size_t i;
	double v;

	(void)state;
	assert_string_equal(dem_dim_format((dem_dim_t){ -1, 0, -1, 0, 0 }, unit,
					   sizeof unit), "m^-1 s^-1");
	assert_string_equal(dem_dim_format((dem_dim_t){ 2, 1, -2, 0, 0 }, unit,
					   sizeof unit), "m^2 kg s^-2");
	assert_string_equal(dem_dim_format(DEM_DIM_DENSITY, unit, sizeof unit),
			    "kg/m^3");
	assert_string_equal(dem_dim_format(DEM_DIM_TEMPERATURE, unit,
					   sizeof unit), "K");
	assert_string_equal(dem_dim_format(PA_PER_K, unit, sizeof unit),
			    "m^-1 kg s^-2 K^-1");
	assert_string_equal(dem_dim_format((dem_dim_t){ 0, 0, 0, 1, -1 }, unit,
					   sizeof unit), "rad K^-1");
	for (i = 0; i < COUNT(dims); i++) {
		dem_dim_format(dims[i], unit, sizeof unit);
		snprintf(text, sizeof text, "0.0007 %s", unit);
		if (dem_units_parse(text, dims[i], &v, why, sizeof why) != 0 ||
		    v != 0.0007)
			fail_msg("'%s' does not read back: %s", text, why);
	}
}

/* Words for messages: article, plural, and the generic fallback. */
static void test_describe(void **state)
{
	char buf[96];

	(void)state;
	assert_string_equal(dem_dim_describe(DEM_DIM_LENGTH, 0, buf, sizeof buf),
			    "a length");
	assert_string_equal(dem_dim_describe(DEM_DIM_ACCEL, 0, buf, sizeof buf),
			    "an acceleration");
	assert_string_equal(dem_dim_describe(DEM_DIM_NONE, 0, buf, sizeof buf),
			    "a number");
	assert_string_equal(dem_dim_describe(DEM_DIM_VELOCITY, 1, buf,
					     sizeof buf), "velocities");
	assert_string_equal(dem_dim_describe((dem_dim_t){ -1, 0, -1, 0, 0 }, 0,
					     buf, sizeof buf),
			    "a quantity in m^-1 s^-1");
	assert_string_equal(dem_dim_example(DEM_DIM_VELOCITY, buf, sizeof buf),
			    "46.5 m/s");
	assert_string_equal(dem_dim_describe(DEM_DIM_TEMPERATURE, 0, buf,
					     sizeof buf), "a temperature");
	assert_string_equal(dem_dim_describe(DEM_DIM_TEMPERATURE, 1, buf,
					     sizeof buf), "temperatures");
	assert_string_equal(dem_dim_example(DEM_DIM_TEMPERATURE, buf,
					    sizeof buf), "293 K");
}

/* dem_dim_equal compares all five exponents. */
static void test_dim_equal(void **state)
{
	(void)state;
	assert_true(dem_dim_equal(DEM_DIM_FORCE, (dem_dim_t){ 1, 1, -2, 0, 0 }));
	assert_false(dem_dim_equal(DEM_DIM_LENGTH, DEM_DIM_ANGLE));
	assert_false(dem_dim_equal(DEM_DIM_NONE, DEM_DIM_ANGLE));
	assert_false(dem_dim_equal(DEM_DIM_PRESSURE, DEM_DIM_FORCE));
	assert_false(dem_dim_equal(DEM_DIM_NONE, DEM_DIM_TEMPERATURE));
	assert_false(dem_dim_equal(DEM_DIM_PRESSURE, PA_PER_K));
	assert_true(dem_dim_equal(DEM_DIM_TEMPERATURE,
				  (dem_dim_t){ 0, 0, 0, 0, 1 }));
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_accepted),
		cmocka_unit_test(test_rejected),
		cmocka_unit_test(test_why_buffer),
		cmocka_unit_test(test_long_number),
		cmocka_unit_test(test_si_names),
		cmocka_unit_test(test_format_round_trip),
		cmocka_unit_test(test_describe),
		cmocka_unit_test(test_dim_equal),
	};

	return cmocka_run_group_tests(tests, NULL, NULL);
}
