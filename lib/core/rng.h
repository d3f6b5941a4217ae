/* rng.h - seeded random numbers through GSL (never rand()).  One generator
 * is made in main from --seed, or from a drawn seed that the program writes
 * into its output header, and passed down. */
#ifndef DEM_CORE_RNG_H
#define DEM_CORE_RNG_H

#include <gsl/gsl_rng.h>

/* A new generator (mt19937).  If *have_seed is 0 a seed is drawn from
 * /dev/urandom (or the clock), stored in *seed, and *have_seed set.
 * NULL when out of memory. */
gsl_rng *dem_rng_new(int *have_seed, unsigned long *seed);

/* A second independent stream derived from the same seed (e.g. positions
 * apart from radii), so either can be replayed alone. */
gsl_rng *dem_rng_derive(unsigned long seed, unsigned long stream);

#endif
