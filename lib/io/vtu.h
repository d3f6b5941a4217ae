/* vtu.h - hexahedral meshes and their fields as VTK XML UnstructuredGrid
 * (.vtu) files for ParaView (demshot --vtu, demform --vtu).
 *
 * The file holds the mesh in its reference coordinates (POINTS), one
 * VTK_HEXAHEDRON (type 12) cell per element, whose node order is hex8.h's
 * (the same as VTK's), and the fields given:
 *
 *   point data  displacement    3 components (m); ParaView's "Warp By
 *                               Vector" shows the deformed shape
 *   cell data   stress          6 components xx yy zz xy yz xz (Pa), the
 *                               order ParaView reads as a symmetric tensor
 *               von_mises       sqrt(3 J2) of the stress (Pa)
 *               strain          6 components, tensor shears (eps_xy =
 *                               gamma_xy / 2), same order
 *               plastic_strain  the effective plastic strain
 *
 * ASCII (every double to 17 significant digits at most, read back exactly)
 * or binary: inline base64, little-endian, a UInt64 byte count before each
 * array, count and data encoded as one base64 run (as VTK writes
 * uncompressed data).  The file is written under a temporary name and
 * renamed when complete; memory beyond the caller's arrays is a few kB.
 */
#ifndef DEM_IO_VTU_H
#define DEM_IO_VTU_H

#include "core/error.h"
#include "mesh/mesh.h"

/* The fields to write; any may be NULL (left out). */
typedef struct dem_vtu_fields {
	const double *u;        /* 3 per node */
	const double *sig;      /* 6 per element (Voigt: xx yy zz xy yz zx) */
	const double *eps;      /* 6 per element, engineering shears */
	const double *ep;       /* 1 per element */
} dem_vtu_fields_t;

/* Write mesh m and fields f to path (binary: base64 inline data, else
 * ASCII).  A value that is not finite is refused (DEM_ENUMERIC naming the
 * node or element) and no file is left; DEM_EIO when path cannot be
 * written. */
int dem_vtu_write(const char *path, const dem_mesh_t *m,
		  const dem_vtu_fields_t *f, int binary, dem_error_t *e);

#endif
