#include "core/rng.h"

#include <stdio.h>
#include <time.h>

static unsigned long draw_seed(void)
{
	unsigned long s = 0;
	FILE *f = fopen("/dev/urandom", "rb");
	if (f) {
		if (fread(&s, sizeof s, 1, f) != 1)
			s = 0;
		fclose(f);
	}
	if (!s)
		s = (unsigned long)time(NULL);
	return s & 0xffffffffUL;        /* short enough to retype */
}

gsl_rng *dem_rng_new(int *have_seed, unsigned long *seed)
{
	if (!*have_seed) {
		*seed = draw_seed();
		*have_seed = 1;
	}
	gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
	if (r)
		gsl_rng_set(r, *seed);
	return r;
}

gsl_rng *dem_rng_derive(unsigned long seed, unsigned long stream)
{
	gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
	/* splitmix-style scrambling keeps derived seeds apart */
	unsigned long long z = (unsigned long long)seed + 0x9e3779b97f4a7c15ULL * (stream + 1);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
	z ^= z >> 31;
	if (r)
		gsl_rng_set(r, (unsigned long)(z & 0xffffffffUL));
	return r;
}
