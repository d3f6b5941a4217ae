/* gridmesh.h - a structured mesh of the tensor grid gx x gy x gz (nx, ny,
 * nz elements), numbered as mesh/mesh.h says, built here so that a test of a
 * reader or a profile does not depend on the mesher; free it with
 * dem_mesh_free(). */
#ifndef DEM_TEST_GRIDMESH_H
#define DEM_TEST_GRIDMESH_H

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "mesh/mesh.h"

static void make_mesh(dem_mesh_t *m, int nx, int ny, int nz, const double *gx,
		      const double *gy, const double *gz)
{
	memset(m, 0, sizeof *m);
	m->nx = nx;
	m->ny = ny;
	m->nz = nz;
	m->gx = malloc((nx + 1) * sizeof(double));
	m->gy = malloc((ny + 1) * sizeof(double));
	m->gz = malloc((nz + 1) * sizeof(double));
	memcpy(m->gx, gx, (nx + 1) * sizeof(double));
	memcpy(m->gy, gy, (ny + 1) * sizeof(double));
	memcpy(m->gz, gz, (nz + 1) * sizeof(double));
	m->nn = (size_t)(nx + 1) * (ny + 1) * (nz + 1);
	m->ne = (size_t)nx * ny * nz;
	m->X = malloc(3 * m->nn * sizeof(double));
	m->hex = malloc(8 * m->ne * sizeof(uint32_t));
	m->fix = calloc(m->nn, 1);
	for (int k = 0; k <= nz; k++)
		for (int j = 0; j <= ny; j++)
			for (int i = 0; i <= nx; i++) {
				size_t n = dem_mesh_node(m, i, j, k);
				m->X[3 * n] = gx[i];
				m->X[3 * n + 1] = gy[j];
				m->X[3 * n + 2] = gz[k];
			}
	static const int di[8] = {0, 1, 1, 0, 0, 1, 1, 0}, dj[8] = {0, 0, 1, 1, 0, 0, 1, 1},
			 dk[8] = {0, 0, 0, 0, 1, 1, 1, 1};
	for (int k = 0; k < nz; k++)
		for (int j = 0; j < ny; j++)
			for (int i = 0; i < nx; i++)
				for (int c = 0; c < 8; c++)
					m->hex[8 * dem_mesh_elem(m, i, j, k) + c] =
						(uint32_t)dem_mesh_node(m, i + di[c], j + dj[c], k + dk[c]);
}

#endif
