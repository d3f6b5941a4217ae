/* dense.c - small dense linear systems (see dense.h). */
#include "fe/dense.h"

#include <math.h>

int dem_dense_solve(int n, double *A, int nrhs, double *B)
{
	for (int k = 0; k < n; k++) {
		int piv = k;
		for (int i = k + 1; i < n; i++)
			if (fabs(A[i * n + k]) > fabs(A[piv * n + k]))
				piv = i;
		if (!(fabs(A[piv * n + k]) > 0))
			return -1;
		if (piv != k) {
			for (int j = 0; j < n; j++) {
				double t = A[k * n + j];
				A[k * n + j] = A[piv * n + j];
				A[piv * n + j] = t;
			}
			for (int j = 0; j < nrhs; j++) {
				double t = B[k * nrhs + j];
				B[k * nrhs + j] = B[piv * nrhs + j];
				B[piv * nrhs + j] = t;
			}
		}
		for (int i = k + 1; i < n; i++) {
			double l = A[i * n + k] / A[k * n + k];
			if (l == 0)
				continue;
			for (int j = k; j < n; j++)
				A[i * n + j] -= l * A[k * n + j];
			for (int j = 0; j < nrhs; j++)
				B[i * nrhs + j] -= l * B[k * nrhs + j];
		}
	}
	for (int k = n - 1; k >= 0; k--)
		for (int j = 0; j < nrhs; j++) {
			double s = B[k * nrhs + j];
			for (int i = k + 1; i < n; i++)
				s -= A[k * n + i] * B[i * nrhs + j];
			B[k * nrhs + j] = s / A[k * n + k];
		}
	return 0;
}
