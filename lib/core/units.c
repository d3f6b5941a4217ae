/* units.c - quantities with units, converted to SI.
 *
 * A quantity is "NUMBER [UNIT]" where UNIT is a product of factors, each a
 * base unit with an optional SI prefix and an optional integer exponent,
 * joined by '*', '/' or a space (the SI brochure writes "N m" for N*m):
 * "0.7 mm", "7800 kg/m^3", "9.81 m/s^2", "200 N/mm^2", "100 1/s".
 *
 * Powers of ten (prefixes, and the 1e-3 of the gram) are not multiplied in
 * floating point: they are added to the number's own decimal exponent and the
 * result is read by one strtod, so "0.7 mm" gives exactly the double nearest
 * to 0.0007, the same double as "0.0007".  Only degrees carry a factor that is
 * not a power of ten.
 *
 * Temperatures are absolute, in kelvin: a unit here is a factor, and degC
 * (or degF) would need an offset, which "5 degC/s" or "Pa/degC" could not
 * apply consistently.  They are refused with a hint, not misread.
 */
#include "core/units.h"

#include "core/consts.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* Exponents beyond these are certainly typing errors, and keep the sums
 * far from the range of signed char and long. */
#define MAX_DIM_EXP 60
#define MAX_EXP10 100000L

struct base_unit {
	const char *name;
	dem_dim_t dim;
	int exp10;      /* the unit is 10^exp10 SI units (g = 1e-3 kg) */
	int degrees;    /* times pi/180 */
	int prefixable;
};

static const struct base_unit base_units[] = {
	{ "m",   DEM_DIM_LENGTH,   0,  0, 1 },
	{ "s",   DEM_DIM_TIME,     0,  0, 1 },
	{ "g",   DEM_DIM_MASS,     -3, 0, 1 },
	{ "N",   DEM_DIM_FORCE,    0,  0, 1 },
	{ "Pa",  DEM_DIM_PRESSURE, 0,  0, 1 },
	{ "rad", DEM_DIM_ANGLE,    0,  0, 1 },
	{ "deg", DEM_DIM_ANGLE,    0,  1, 0 },
	{ "K",   DEM_DIM_TEMPERATURE, 0, 0, 1 },
};

/* Offset scales of temperature, known only to be refused. */
static const char *const offset_scales[] = {
	"degC", "degF", "\xc2\xb0""C", "\xc2\xb0""F", "C", "F",
};

struct prefix {
	const char *name;
	int exp10;
};

/* Micro has three spellings: u, the micro sign U+00B5 and Greek mu U+03BC. */
static const struct prefix prefixes[] = {
	{ "n", -9 }, { "u", -6 }, { "\xc2\xb5", -6 }, { "\xce\xbc", -6 },
	{ "m", -3 }, { "c", -2 }, { "k", 3 }, { "M", 6 }, { "G", 9 },
};

/* Names for messages and --dump-scene.  Every si string here must parse
 * back to its own dimension, so a dumped scene loads again. */
struct dim_name {
	dem_dim_t dim;
	const char *si;
	const char *word;       /* singular, without article */
	const char *words;      /* plural */
	const char *example;    /* a typical value, for "(e.g. '...')" */
};

static const struct dim_name dim_names[] = {
	{ DEM_DIM_NONE, "", "number", "numbers", "0.5" },
	{ DEM_DIM_LENGTH, "m", "length", "lengths", "0.7 mm" },
	{ DEM_DIM_MASS, "kg", "mass", "masses", "2 g" },
	{ DEM_DIM_TIME, "s", "time", "times", "1 us" },
	{ DEM_DIM_ANGLE, "rad", "angle", "angles", "30 deg" },
	{ DEM_DIM_VELOCITY, "m/s", "velocity", "velocities", "46.5 m/s" },
	{ DEM_DIM_ACCEL, "m/s^2", "acceleration", "accelerations",
	  "9.81 m/s^2" },
	{ DEM_DIM_FORCE, "N", "force", "forces", "10 N" },
	{ DEM_DIM_PRESSURE, "Pa", "pressure", "pressures", "72 GPa" },
	{ DEM_DIM_DENSITY, "kg/m^3", "density", "densities", "7800 kg/m^3" },
	{ DEM_DIM_RATE, "1/s", "rate", "rates", "100 1/s" },
	{ DEM_DIM_TEMPERATURE, "K", "temperature", "temperatures", "293 K" },
	{ { 2, 0, 0, 0, 0 }, "m^2", "area", "areas", "1 mm^2" },
	{ { 3, 0, 0, 0, 0 }, "m^3", "volume", "volumes", "1 mm^3" },
	{ { 0, 1, -2, 0, 0 }, "N/m", "stiffness", "stiffnesses", "1e6 N/m" },
	{ { 0, 0, -1, 1, 0 }, "rad/s", "angular velocity", "angular velocities",
	  "10 rad/s" },
};

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

/* The exponents of dem_dim_t: L, M, T, A, Th. */
#define NDIM 5

int dem_dim_equal(dem_dim_t a, dem_dim_t b)
{
	return a.L == b.L && a.M == b.M && a.T == b.T && a.A == b.A &&
	       a.Th == b.Th;
}

static const struct dim_name *find_dim_name(dem_dim_t d)
{
	size_t i;

	for (i = 0; i < COUNT(dim_names); i++)
		if (dem_dim_equal(dim_names[i].dim, d))
			return &dim_names[i];
	return NULL;
}

const char *dem_dim_si_name(dem_dim_t d)
{
	const struct dim_name *n = find_dim_name(d);

	/* Without a buffer from the caller there is nowhere to build a
	 * generic form; dem_dim_format() does that. */
	return n ? n->si : "?";
}

/* The generic SI form in the order of the struct: "m^-1 kg s^-1". */
static void format_generic(dem_dim_t d, char *buf, size_t len)
{
	static const char *const sym[NDIM] = { "m", "kg", "s", "rad", "K" };
	int exp[NDIM] = { d.L, d.M, d.T, d.A, d.Th };
	size_t used = 0;
	int i, k;

	buf[0] = '\0';
	for (i = 0; i < NDIM; i++) {
		if (exp[i] == 0 || used >= len)
			continue;
		if (exp[i] == 1)
			k = snprintf(buf + used, len - used, "%s%s",
				     used ? " " : "", sym[i]);
		else
			k = snprintf(buf + used, len - used, "%s%s^%d",
				     used ? " " : "", sym[i], exp[i]);
		if (k > 0)
			used += (size_t)k;
	}
}

const char *dem_dim_format(dem_dim_t d, char *buf, size_t len)
{
	const struct dim_name *n = find_dim_name(d);

	if (len == 0)
		return buf;
	if (n)
		snprintf(buf, len, "%s", n->si);
	else
		format_generic(d, buf, len);
	return buf;
}

const char *dem_dim_describe(dem_dim_t d, int plural, char *buf, size_t len)
{
	const struct dim_name *n = find_dim_name(d);
	char si[64];
	const char *w;

	if (len == 0)
		return buf;
	if (!n) {
		format_generic(d, si, sizeof si);
		snprintf(buf, len, "%s in %s",
			 plural ? "quantities" : "a quantity", si);
		return buf;
	}
	w = plural ? n->words : n->word;
	if (plural)
		snprintf(buf, len, "%s", w);
	else
		snprintf(buf, len, "%s %s",
			 strchr("aeiou", w[0]) ? "an" : "a", w);
	return buf;
}

const char *dem_dim_example(dem_dim_t d, char *buf, size_t len)
{
	const struct dim_name *n = find_dim_name(d);
	char si[64];

	if (len == 0)
		return buf;
	if (n) {
		snprintf(buf, len, "%s", n->example);
	} else {
		format_generic(d, si, sizeof si);
		snprintf(buf, len, "1 %s", si);
	}
	return buf;
}

/* What has been read of the unit expression so far. */
struct unit_acc {
	int dim[NDIM];
	long exp10;
	int degrees;
};

static int is_unit_char(unsigned char c)
{
	/* ASCII letters, and any byte of a UTF-8 sequence (for µ and μ) */
	return isalpha(c) || c >= 0x80;
}

static const struct base_unit *find_base(const char *name, size_t n,
					 int need_prefixable)
{
	size_t i;

	for (i = 0; i < COUNT(base_units); i++) {
		const struct base_unit *b = &base_units[i];

		if (strlen(b->name) == n && memcmp(b->name, name, n) == 0 &&
		    (!need_prefixable || b->prefixable))
			return b;
	}
	return NULL;
}

/* Match a unit name: a base unit alone first, so "m" is the metre and "Pa"
 * the pascal, then a prefix and a base unit ("mm", "ms", "MPa", "kg"). */
static const struct base_unit *find_unit(const char *name, size_t n,
					 int *exp10)
{
	const struct base_unit *b = find_base(name, n, 0);
	size_t i;

	*exp10 = 0;
	if (b)
		return b;
	for (i = 0; i < COUNT(prefixes); i++) {
		size_t pl = strlen(prefixes[i].name);

		if (pl >= n || memcmp(prefixes[i].name, name, pl) != 0)
			continue;
		b = find_base(name + pl, n - pl, 1);
		if (b) {
			*exp10 = prefixes[i].exp10;
			return b;
		}
	}
	return NULL;
}

static int is_offset_scale(const char *name, size_t n)
{
	size_t i;

	for (i = 0; i < COUNT(offset_scales); i++)
		if (strlen(offset_scales[i]) == n &&
		    memcmp(offset_scales[i], name, n) == 0)
			return 1;
	return 0;
}

/* Read "^N" after a unit name: a signed integer of one or two digits. */
static int read_exponent(const char **pp, int *exp)
{
	const char *p = *pp;
	int sign = 1, v = 0, nd = 0;

	*exp = 1;
	if (*p != '^')
		return 0;
	p++;
	if (*p == '-' || *p == '+')
		sign = *p++ == '-' ? -1 : 1;
	while (isdigit((unsigned char)*p) && nd < 3) {
		v = 10 * v + (*p++ - '0');
		nd++;
	}
	if (nd == 0 || nd > 2)
		return -1;
	*exp = sign * v;
	*pp = p;
	return 0;
}

/* Read one factor ("mm^2") at *pp and add it to acc with sign op (+1 for a
 * product, -1 after '/').  Returns 0 or -1 with why. */
static int read_factor(const char **pp, int op, struct unit_acc *acc,
		       char *why, size_t whylen)
{
	const char *p = *pp, *name = p;
	const struct base_unit *b;
	int pexp10, exp;
	size_t n;

	while (is_unit_char((unsigned char)*p))
		p++;
	n = (size_t)(p - name);
	if (n == 0) {
		if (*name)
			snprintf(why, whylen, "expected a unit at '%s'", name);
		else
			snprintf(why, whylen, "expected a unit at the end");
		return -1;
	}
	b = find_unit(name, n, &pexp10);
	if (!b) {
		snprintf(why, whylen, "unknown unit '%.*s'%s", (int)n, name,
			 is_offset_scale(name, n) ? " (temperatures are "
			 "absolute, in kelvin: '293 K')" : "");
		return -1;
	}
	if (read_exponent(&p, &exp) < 0) {
		snprintf(why, whylen, "bad exponent after unit '%.*s'",
			 (int)n, name);
		return -1;
	}
	exp *= op;
	acc->dim[0] += exp * b->dim.L;
	acc->dim[1] += exp * b->dim.M;
	acc->dim[2] += exp * b->dim.T;
	acc->dim[3] += exp * b->dim.A;
	acc->dim[4] += exp * b->dim.Th;
	acc->exp10 += (long)exp * (pexp10 + b->exp10);
	acc->degrees += exp * b->degrees;
	*pp = p;
	return 0;
}

static int dims_sane(const struct unit_acc *acc)
{
	int i;

	for (i = 0; i < NDIM; i++)
		if (acc->dim[i] > MAX_DIM_EXP || acc->dim[i] < -MAX_DIM_EXP)
			return 0;
	return acc->exp10 <= MAX_EXP10 && acc->exp10 >= -MAX_EXP10 &&
	       acc->degrees <= MAX_DIM_EXP && acc->degrees >= -MAX_DIM_EXP;
}

static const char *skip_space(const char *p)
{
	while (isspace((unsigned char)*p))
		p++;
	return p;
}

/* Parse the unit expression at p (not empty) into acc. */
static int parse_unit(const char *p, struct unit_acc *acc, char *why,
		      size_t whylen)
{
	int op = 1;

	/* "1/s": a leading 1 stands for an empty numerator */
	if (p[0] == '1' && *skip_space(p + 1) == '/') {
		p = skip_space(p + 1) + 1;
		p = skip_space(p);
		op = -1;
	}
	for (;;) {
		if (read_factor(&p, op, acc, why, whylen) < 0)
			return -1;
		if (!dims_sane(acc)) {
			snprintf(why, whylen, "unit exponent too large");
			return -1;
		}
		p = skip_space(p);
		if (*p == '\0')
			return 0;
		if (*p == '*' || *p == '/') {
			op = *p == '/' ? -1 : 1;
			p = skip_space(p + 1);
		} else if (is_unit_char((unsigned char)*p)) {
			op = 1;         /* "N m": a space multiplies */
		} else {
			snprintf(why, whylen, "trailing garbage '%s'", p);
			return -1;
		}
	}
}

/* Does p start with inf, infinity or nan (as strtod or YAML's .inf spell
 * them)?  Those are numbers, but not finite ones. */
static int is_nonfinite_word(const char *p)
{
	size_t n;

	if (*p == '.')
		p++;
	n = strspn(p, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ");
	if (*skip_space(p + n) != '\0')
		return 0;
	return (n == 3 && strncasecmp(p, "inf", 3) == 0) ||
	       (n == 8 && strncasecmp(p, "infinity", 8) == 0) ||
	       (n == 3 && strncasecmp(p, "nan", 3) == 0);
}

struct number {
	const char *mant;       /* sign, digits, point, digits */
	int mantlen;
	long exp10;             /* the written exponent, clamped */
	const char *end;
};

/* Scan a decimal number: [+-] digits [. digits] [e [+-] digits].  Only
 * decimal: strtod would also take hex, inf and nan. */
static int scan_number(const char *p, struct number *num)
{
	const char *q = p;
	int ndig = 0, esign = 1;
	long e = 0;

	if (*q == '+' || *q == '-')
		q++;
	while (isdigit((unsigned char)*q)) {
		q++;
		ndig++;
	}
	if (*q == '.') {
		q++;
		while (isdigit((unsigned char)*q)) {
			q++;
			ndig++;
		}
	}
	if (ndig == 0)
		return -1;
	num->mant = p;
	num->mantlen = (int)(q - p);
	num->exp10 = 0;
	if ((*q == 'e' || *q == 'E') &&
	    (isdigit((unsigned char)q[1]) ||
	     ((q[1] == '+' || q[1] == '-') && isdigit((unsigned char)q[2])))) {
		q++;
		if (*q == '+' || *q == '-')
			esign = *q++ == '-' ? -1 : 1;
		while (isdigit((unsigned char)*q)) {
			if (e < MAX_EXP10 * 10)
				e = 10 * e + (*q - '0');
			q++;
		}
		num->exp10 = esign * e;
	}
	num->end = q;
	return 0;
}

/* The value of the number times 10^exp10, correctly rounded. */
static int number_value(const struct number *num, long exp10, double *v)
{
	char small[64], *buf = small;
	size_t need = (size_t)num->mantlen + 32;

	if (need > sizeof small) {
		buf = malloc(need);
		if (!buf)
			return -1;
	}
	snprintf(buf, need, "%.*se%ld", num->mantlen, num->mant,
		 num->exp10 + exp10);
	*v = strtod(buf, NULL);
	if (buf != small)
		free(buf);
	return 0;
}

/* Where the unit expression may start: a unit name, or the 1 of "1/s". */
static int starts_unit(const char *p)
{
	return is_unit_char((unsigned char)*p) ||
	       (p[0] == '1' && *skip_space(p + 1) == '/');
}

static void dim_mismatch(const char *unit, dem_dim_t got, dem_dim_t want,
			 char *why, size_t whylen)
{
	char g[96], w[96];

	dem_dim_describe(got, 0, g, sizeof g);
	dem_dim_describe(want, 0, w, sizeof w);
	snprintf(why, whylen, "unit '%s' is %s, expected %s", unit, g, w);
}

int dem_units_parse(const char *text, dem_dim_t want, double *si,
		    char *why, size_t whylen)
{
	struct unit_acc acc = { { 0, 0, 0, 0, 0 }, 0, 0 };
	struct number num;
	const char *p = skip_space(text), *unit;
	char unitbuf[128];
	dem_dim_t got;
	size_t n;
	double v;
	int i;

	if (whylen > 0)
		why[0] = '\0';
	if (scan_number(p, &num) < 0) {
		p += (*p == '+' || *p == '-');
		snprintf(why, whylen, is_nonfinite_word(p) ?
			 "not finite" : "not a number");
		return -1;
	}
	unit = skip_space(num.end);
	if (*unit != '\0') {
		if (!starts_unit(unit) ||
		    (unit == num.end && !is_unit_char((unsigned char)*unit))) {
			snprintf(why, whylen, "trailing garbage '%s'", unit);
			return -1;
		}
		if (parse_unit(unit, &acc, why, whylen) < 0)
			return -1;
		got = (dem_dim_t){ (signed char)acc.dim[0],
				   (signed char)acc.dim[1],
				   (signed char)acc.dim[2],
				   (signed char)acc.dim[3],
				   (signed char)acc.dim[4] };
		if (!dem_dim_equal(got, want)) {
			/* name the unit as written, without trailing space */
			n = strlen(unit);
			while (n > 0 && isspace((unsigned char)unit[n - 1]))
				n--;
			snprintf(unitbuf, sizeof unitbuf, "%.*s", (int)n, unit);
			dim_mismatch(unitbuf, got, want, why, whylen);
			return -1;
		}
	}
	if (number_value(&num, acc.exp10, &v) < 0) {
		snprintf(why, whylen, "out of memory");
		return -1;
	}
	for (i = 0; i < acc.degrees; i++)
		v *= DEM_PI / 180;
	for (i = 0; i > acc.degrees; i--)
		v /= DEM_PI / 180;
	if (!isfinite(v)) {
		snprintf(why, whylen, "not finite");
		return -1;
	}
	*si = v;
	return 0;
}
