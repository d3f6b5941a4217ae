/* mesh.h - structured hexahedral meshes of a box, for the explicit block of
 * demshot (Ch. 7.5, Figs. 7.13 and 8.3) and the implicit plate of demform
 * (Ch. 8.6).
 *
 * Each axis is meshed on its own (dem_axis_t): a fine region of uniform
 * elements of size h, and outside it elements growing geometrically by
 * `ratio` per element (capped at hmax) up to the box ends, the last element
 * on each side stretched or shrunk so the grid ends exactly on the box.  The
 * mesh is the tensor product of the three axes' grid lines, so faces are
 * planes and every element is a rectangular box in the reference state.
 *
 * Numbering.  Grid lines i = 0..nx along x (coordinate gx[i]), likewise j,
 * k; node (i, j, k) is i + (nx+1) (j + (ny+1) k); element (i, j, k) is
 * i + nx (j + ny k), with its 8 nodes in the order of hex8.h.  z is the
 * thickness direction; the top face (z = gz[nz]) is the peened surface.
 *
 * Boundary conditions by face: each of the six faces is free, fixed (all
 * three displacements zero) or fixed in its normal direction (a roller).  A
 * node on several faces takes the union of their constraints.  The x and y
 * side pairs may instead be periodic (dem_mesh_set_periodic): each node of
 * the xmax face is tied to the node of the xmin face with the same j, k,
 * and each node of ymax to its ymin partner, a corner to the one node of
 * the (xmin, ymin) edge, so that every tied set has one master.  The block
 * then stands for one cell of a surface peened all over the same way (a
 * point of a large plate), with no mean in-plane strain: a slave's
 * displacement is its master's.
 */
#ifndef DEM_MESH_MESH_H
#define DEM_MESH_MESH_H

#include <stddef.h>
#include <stdint.h>

#include "core/error.h"

/* One axis: the box [lo, hi], the fine region [fine_lo, fine_hi] (inside the
 * box; fine_lo == fine_hi == lo meshes everything by grading from lo, and
 * fine_lo = lo, fine_hi = hi gives a uniform axis), element size h in it,
 * growth ratio >= 1 outside, hmax >= h the largest element (0: no cap). */
typedef struct dem_axis {
	double lo, hi;
	double fine_lo, fine_hi;
	double h;
	double ratio;
	double hmax;
} dem_axis_t;

/* Grid lines of one axis (malloc'ed, *n + 1 values from lo to hi,
 * increasing); *n elements.  DEM_EINPUT for an impossible spec. */
int dem_axis_grid(const dem_axis_t *a, double **g, int *n, dem_error_t *e);

/* The grid lines of na <= 3 axes (x, y, z in that order) by
 * dem_axis_grid: g[a] and n[a] for each; on error a message naming the
 * axis ("mesh y axis: ...") and nothing left allocated. */
int dem_mesh_axes(const dem_axis_t *ax, int na, double **g, int *n, dem_error_t *e);

enum dem_face { DEM_XMIN, DEM_XMAX, DEM_YMIN, DEM_YMAX, DEM_ZMIN, DEM_ZMAX };
typedef enum dem_bc { DEM_BC_FREE = 0, DEM_BC_FIXED, DEM_BC_NORMAL, DEM_BC_PERIODIC } dem_bc_t;

/* Node constraint bits */
#define DEM_FIX_X 1u
#define DEM_FIX_Y 2u
#define DEM_FIX_Z 4u

typedef struct dem_mesh {
	int nx, ny, nz;          /* elements along each axis */
	double *gx, *gy, *gz;    /* grid lines (nx+1, ny+1, nz+1 values) */
	size_t nn, ne;           /* nodes, elements */
	double *X;               /* reference coordinates, 3 per node (x, y, z) */
	uint32_t *hex;           /* 8 node numbers per element */
	uint8_t *fix;            /* DEM_FIX_* bits per node */
	size_t ntie;             /* periodic ties (0: none) */
	uint32_t *tie;           /* 2 per tie: the slave node, then its master */
} dem_mesh_t;

/* Build the mesh of the box given by three axes.  DEM_EINPUT for a bad
 * axis, DEM_EIO when out of memory. */
int dem_mesh_box(dem_mesh_t *m, const dem_axis_t ax[3], dem_error_t *e);
/* The same from given grid lines g[a] (n[a] + 1 increasing values each,
 * malloc'ed; the mesh takes them over, and frees them on error too). */
int dem_mesh_grid(dem_mesh_t *m, double *g[3], const int n[3], dem_error_t *e);
void dem_mesh_free(dem_mesh_t *m);

/* Set the node constraints from the six faces' conditions (indexed by enum
 * dem_face); clears earlier ones.  A periodic face constrains nothing here:
 * its ties are dem_mesh_set_periodic's. */
void dem_mesh_set_bc(dem_mesh_t *m, const dem_bc_t bc[6]);

/* Tie the xmax face to the xmin face (px) and the ymax face to the ymin
 * face (py), replacing earlier ties (px = py = 0: none).  A slave is never
 * a master.  DEM_EIO when out of memory. */
int dem_mesh_set_periodic(dem_mesh_t *m, int px, int py, dem_error_t *e);

/* Node and element numbers from grid indices. */
static inline size_t dem_mesh_node(const dem_mesh_t *m, int i, int j, int k)
{
	return (size_t)i + (size_t)(m->nx + 1) * ((size_t)j + (size_t)(m->ny + 1) * (size_t)k);
}

static inline size_t dem_mesh_elem(const dem_mesh_t *m, int i, int j, int k)
{
	return (size_t)i + (size_t)m->nx * ((size_t)j + (size_t)m->ny * (size_t)k);
}

/* Gather element el's reference coordinates, component-major as hex8.h
 * wants (x[0..7], y[8..15], z[16..23]), displaced by u (3 per node, may
 * be NULL). */
void dem_mesh_gather(const dem_mesh_t *m, size_t el, const double *u, double x[24]);

#endif
