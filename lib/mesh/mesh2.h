/* mesh2.h - quadrilateral meshes for the 2D explicit engine
 * (fe/explicit2d.h): the structured mesh of a rectangle, the block (plane
 * strain, Ch. 7.4; axisymmetric, Ch. 7.5.1), and the O-grid of a disk, the
 * finite element shot of Ch. 7.4 (dem_mesh2_disk, at the end).
 *
 * The 2D twin of mesh.h: each axis is meshed by dem_axis_grid (mesh.h: a
 * fine region of uniform elements, geometric grading outside it, capped at
 * hmax), and the mesh is the tensor product of the two axes' grid lines, so
 * every element is a rectangle in the reference state.  y is the thickness
 * direction; the top edge (y = gy[ny]) is the peened surface.  For an
 * axisymmetric model x is the radius r (the x axis must then start at
 * r >= 0; nodes at r = 0 lie on the axis).
 *
 * Numbering.  Grid lines i = 0..nx along x (coordinate gx[i]), j = 0..ny
 * along y; node (i, j) is i + (nx+1) j; element (i, j) is i + nx j, with its
 * 4 nodes counter-clockwise from (i, j) as fe/quad4.h wants.
 *
 * Boundary conditions by edge (enum dem_face's first four: DEM_XMIN,
 * DEM_XMAX, DEM_YMIN, DEM_YMAX): each edge is free, fixed (both
 * displacements zero) or fixed in its normal direction (a roller).  A node
 * on two edges takes the union of their constraints.  No periodic ties.
 */
#ifndef DEM_MESH_MESH2_H
#define DEM_MESH_MESH2_H

#include <stddef.h>
#include <stdint.h>

#include "core/error.h"
#include "mesh/mesh.h"

typedef struct dem_mesh2 {
	int nx, ny;              /* elements along each axis; 0 for a mesh
				  * without grid lines (dem_mesh2_disk) */
	double *gx, *gy;         /* grid lines (nx+1, ny+1 values); NULL without */
	size_t nn, ne;           /* nodes, elements */
	double *X;               /* reference coordinates, 2 per node (x, y) */
	uint32_t *quad;          /* 4 node numbers per element */
	uint8_t *fix;            /* DEM_FIX_X, DEM_FIX_Y bits per node */
} dem_mesh2_t;

/* Build the mesh of the rectangle given by two axes (ax[0] along x, ax[1]
 * along y).  DEM_EINPUT for a bad axis, DEM_EIO when out of memory.  No
 * constraints (fix all zero). */
int dem_mesh2_rect(dem_mesh2_t *m, const dem_axis_t ax[2], dem_error_t *e);
void dem_mesh2_free(dem_mesh2_t *m);

/* Set the node constraints from the four edges' conditions (indexed by
 * DEM_XMIN..DEM_YMAX); clears earlier ones.  DEM_BC_PERIODIC counts as
 * free. */
void dem_mesh2_set_bc(dem_mesh2_t *m, const dem_bc_t bc[4]);

static inline size_t dem_mesh2_node(const dem_mesh2_t *m, int i, int j)
{
	return (size_t)i + (size_t)(m->nx + 1) * (size_t)j;
}

static inline size_t dem_mesh2_elem(const dem_mesh2_t *m, int i, int j)
{
	return (size_t)i + (size_t)m->nx * (size_t)j;
}

/* Gather element el's reference coordinates, component-major as quad4.h
 * wants (x[0..3], y[4..7]), displaced by u (2 per node, may be NULL). */
void dem_mesh2_gather(const dem_mesh2_t *m, size_t el, const double *u, double x[8]);

/* The segments of the top edge (y = gy[ny]) whose midpoints lie in
 * [x0, x1], left to right, so that the outside (+y) is on each segment's
 * left as contact/disk.h and dem_fe2_add_pressure want: writes 2 node
 * numbers per segment to seg (unless NULL) and returns the count. */
size_t dem_mesh2_top_segments(const dem_mesh2_t *m, double x0, double x1, uint32_t *seg);

/* The 2D mesh as a 3D one (mesh.h) for the streams the 3D programs read
 * (the state stream, VTU): the 2D x-y plane is the 3D x-z plane, the
 * element layer one element thick in y, from -w/2 to w/2.  Node (i, k) of
 * m2 becomes the 3D nodes (i, 0, k) and (i, 1, k); element (i, k) the hex
 * (i, 0, k), the same number.  No constraints.  DEM_EIO without memory. */
int dem_mesh2_extrude(const dem_mesh2_t *m2, double w, dem_mesh_t *m, dem_error_t *e);

/* The 2D fields (explicit2d.h's: u 2 per node, sig and eps 6 per element
 * with zz out of plane, ep 1) on the extruded mesh m: u = (u_x, 0, u_y) on
 * both nodes of a pair; sig = (xx, zz, yy, 0, 0, xy) of the 2D one, as
 * its x, y, z are the 3D x, z, y (eps likewise, ep copied).  Any of
 * the four pairs may be NULL. */
void dem_mesh2_lift(const dem_mesh2_t *m2, const double *u2, const double *sig2,
		    const double *eps2, const double *ep2, double *u, double *sig,
		    double *eps, double *ep);

/* The O-grid of a disk of radius R centred at c (2 values): a square core
 * of half side a = R/2, n x n elements, and four mapped blocks between its
 * sides and the circle, n elements along the arc and m across, each node
 * of a block on the straight line from a point of the square's side
 * (evenly spaced) to a point of the circle (evenly spaced in angle), at
 * j/m of the way.  n = ceil(pi R / (2 h)) so that the rim's segments are
 * no longer than h; m = max(1, round((R - a) / h)).  The elements are
 * then no longer than about h: the core's are 2 a / n = 0.64 h on a side,
 * and the blocks' radial edges (R - a sqrt 2) / m = 0.59 h at the square's
 * corners, the shortest ones (the stable step's measure, quad4.h).
 * 4 n m + n^2 elements, 4 n (m + 1) + (n - 1)^2 nodes.
 *
 * Numbering.  Nodes 0 .. 4n-1 are the rim, counter-clockwise from the
 * angle -45 degrees, on the circle to rounding (returned in *nrim); the
 * other rings of the blocks follow inwards, then the core's inner nodes.
 * Elements counter-clockwise (quad4.h).  The rim's segments with the
 * outside on their left (as contact/disk.h and dem_mesh2_top_segments
 * have it) are (k+1, k), clockwise.  No grid lines (nx = ny = 0, gx = gy =
 * NULL), no constraints.  DEM_EINPUT for R or h not > 0 or more than
 * 10^7 elements (R / h too large), DEM_EIO when out of memory. */
int dem_mesh2_disk(dem_mesh2_t *m, double R, double h, const double c[2], size_t *nrim,
		   dem_error_t *e);

#endif
