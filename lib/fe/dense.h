/* dense.h - small dense linear systems (the static condensation of the
 * incompatible modes in hex8.c and hex8_large.c). */
#ifndef DEM_FE_DENSE_H
#define DEM_FE_DENSE_H

/* Solve A X = B by Gaussian elimination with partial pivoting; A (n x n)
 * and B (n x nrhs) row-major, both overwritten (B by X).  Returns -1 if A
 * is singular (a zero pivot), else 0. */
int dem_dense_solve(int n, double *A, int nrhs, double *B);

#endif
