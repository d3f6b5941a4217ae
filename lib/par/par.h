/* par.h - the few collective operations the explicit stage needs to run
 * on several processes (issue 22), behind one small interface so that MPI
 * stays out of lib/fe and the programs.
 *
 * Two implementations of this header, both in par.c: serial (one rank;
 * every operation leaves its data as it is), the default build's; and on
 * MPI, with -DDEM_MPI and OpenMPI's flags (make MPI=1).
 * A NULL handle is one rank in either build.
 *
 * The ranks form a chain 0, 1, ..., size - 1: rank r shares data with
 * r - 1 below and r + 1 above (the slabs of element layers of
 * lib/fe/explicit.c, bottom to top).  Every operation is collective: each
 * rank calls it, in the same order, with the same sizes.  MPI's errors
 * abort the run (MPI's default handler): a failed collective is not a
 * state to recover from.
 *
 * Determinism: the operations whose results every rank must hold to the
 * bit (the forces on a shared node plane, the sums of energies) fix the
 * order of the additions themselves rather than trust a reduction, which
 * MPI does not promise to give identical bits on all ranks.
 */
#ifndef DEM_PAR_PAR_H
#define DEM_PAR_PAR_H

#include <stddef.h>

#include "core/error.h"

typedef struct dem_par dem_par_t;

/* 1 when built on MPI (make MPI=1), 0 otherwise. */
int dem_par_mpi(void);

/* Start the processes' communication (MPI_Init_thread, OpenMP threads
 * inside each rank make no MPI calls: MPI_THREAD_FUNNELED) with the
 * program's arguments, which MPI may edit; the serial build makes a handle
 * of one rank.  DEM_EIO when MPI cannot start or without memory. */
int dem_par_init(dem_par_t **p, int *argc, char ***argv, dem_error_t *e);
/* End it (MPI_Finalize); NULL: nothing. */
void dem_par_finalize(dem_par_t *p);
/* Stop every rank at once with the exit code (MPI_Abort; serial: exit). */
void dem_par_abort(const dem_par_t *p, int code) __attribute__((noreturn));

int dem_par_rank(const dem_par_t *p);   /* 0 .. size - 1; NULL: 0 */
int dem_par_size(const dem_par_t *p);   /* NULL: 1 */

/* The n values lo (what this rank holds of the data it shares with rank -
 * 1) and hi (with rank + 1) become the sum of the two ranks' values, the
 * lower rank's first: v(r) + v(r + 1) on both ranks, the same bits.  lo is
 * not read on rank 0, hi not on the last rank (either may be NULL there).
 * buf: scratch of 2 n doubles. */
void dem_par_halo_sum(dem_par_t *p, double *lo, double *hi, size_t n, double *buf);

/* v[0..n) becomes the sum over the ranks, added in rank order (0 + 1 +
 * ...), the same bits on every rank.  buf: scratch of size * n doubles. */
void dem_par_sum_ordered(dem_par_t *p, double *v, size_t n, double *buf);

/* The least v over the ranks (exact: a minimum has no rounding). */
double dem_par_min(dem_par_t *p, double v);
/* The largest v over the ranks. */
int dem_par_max_int(dem_par_t *p, int v);

/* buf holds items of unit bytes; rank r has filled items [off[r],
 * off[r + 1]) (off: size + 1 non-decreasing offsets).  Afterwards every
 * rank holds every rank's items. */
void dem_par_gather(dem_par_t *p, void *buf, size_t unit, const size_t *off);

/* n bytes from rank root to every rank. */
void dem_par_bcast(dem_par_t *p, void *buf, size_t n, int root);

/* Wait for every rank. */
void dem_par_barrier(dem_par_t *p);

#endif
