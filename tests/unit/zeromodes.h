/* zeromodes.h - the element tests' count of zero-energy modes: the number
 * of eigenvalues of a symmetric n x n stiffness K below tol times the
 * largest in magnitude, each asserted above -tol times it (K positive
 * semi-definite).  Include after cmocka.h and gsl/gsl_eigen.h. */
#ifndef DEM_TESTS_ZEROMODES_H
#define DEM_TESTS_ZEROMODES_H

#include <stdlib.h>
#include <string.h>

static int zero_modes(const double *K, size_t n, double tol)
{
	double *a = malloc(n * n * sizeof *a);
	assert_non_null(a);
	memcpy(a, K, n * n * sizeof *a);
	gsl_matrix_view A = gsl_matrix_view_array(a, n, n);
	gsl_vector *ev = gsl_vector_alloc(n);
	gsl_eigen_symm_workspace *w = gsl_eigen_symm_alloc(n);
	gsl_eigen_symm(&A.matrix, ev, w);
	double big = 0;
	for (size_t i = 0; i < n; i++)
		big = fmax(big, fabs(gsl_vector_get(ev, i)));
	int zeros = 0;
	for (size_t i = 0; i < n; i++) {
		assert_true(gsl_vector_get(ev, i) > -tol * big);  /* semi-definite */
		zeros += gsl_vector_get(ev, i) < tol * big;
	}
	gsl_eigen_symm_free(w);
	gsl_vector_free(ev);
	free(a);
	return zeros;
}

#endif
