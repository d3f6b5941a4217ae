/* slow.h - the unit tests' sweeps under the sanitizers, which take about
 * three times as long: SLOW_CASES(all, sanitized) is the number of cases
 * a slow sweep runs, all in the plain build, its first `sanitized` ones
 * under AddressSanitizer (which check the memory of the loop each case
 * runs whole). */
#ifndef DEM_TESTS_SLOW_H
#define DEM_TESTS_SLOW_H

#ifdef __SANITIZE_ADDRESS__
#define SLOW_CASES(all, sanitized) (sanitized)
#else
#define SLOW_CASES(all, sanitized) (all)
#endif

#endif
