/* fescene.h - the scene sections the finite element programs share.
 *
 * The `material` section (demshot's block and demform's plate are the same
 * part, so they read the same section):
 *
 *   material:
 *     E: 72 GPa                 # Young's modulus (required)
 *     nu: 0.33                  # Poisson's ratio (required)
 *     rho: 2800 kg/m^3          # density (required by the explicit stage)
 *     yield: 450 MPa            # initial yield stress: switches plasticity on
 *     hardening: 120 MPa        # linear plastic modulus H (default 0)
 *     table:                    # or a hardening table (Table 7.1) instead
 *       strain: [0, 0.0017, 0.0039]          # effective plastic strain
 *       stress: [349.8 MPa, 605.4 MPa, 645.9 MPa]
 *     rate_exponent: 0.0455     # switches rate dependence on (Table 7.2)
 *     rate_ref: 1 1/s           # reference strain rate (default 1/s)
 *
 * Only what is given is simulated: no yield and no table, an elastic
 * material; no rate_exponent, a rate-independent one.
 */
#ifndef DEM_FE_FESCENE_H
#define DEM_FE_FESCENE_H

#include "fe/material.h"
#include "io/scene.h"
#include "mesh/mesh.h"
#include "mesh/mesh2.h"

/* Read the material section and build the material.  need_rho: the
 * density is required (explicit dynamics); otherwise it defaults to 0.
 * Errors are DEM_EINPUT naming file:line:col. */
int dem_scene_material(dem_scene_t *s, int need_rho, dem_mat_t *m,
		       dem_error_t *e);

/* The `block` section: demshot's workpiece, a box meshed finely under the
 * impact area and graded outside it and through the thickness (Figs. 7.13
 * and 8.3), x and y centred on 0, z from -thickness to 0 (the top face,
 * z = 0, is the peened surface):
 *
 *   block:
 *     size: [8 mm, 8 mm, 4 mm]   # x, y extent and thickness (required)
 *     element: 0.05 mm           # element size in the fine region (required)
 *     fine: [5.6 mm, 5.6 mm]     # fine region in x and y, centred (default: all)
 *     fine_depth: 1 mm           # its depth below the top (default: all)
 *     ratio: 1.2                 # geometric growth outside it (default 1.2)
 *     max_element: 1 mm          # largest element (default: no cap)
 *     bc:                        # per face: fixed | normal | free
 *       xmin: normal             # the four sides default to normal
 *       bottom: fixed            # (default fixed)
 *       top: free                # (default free)
 *
 * Builds the mesh with its constraints; DEM_EINPUT naming the key. */
int dem_scene_block(dem_scene_t *s, dem_mesh_t *m, dem_error_t *e);

/* The `block` section of a 2D scene (`dim: 2`, demshot(1)): the block in
 * the x-y plane of mesh2.h, y from -thickness to 0 (the top edge, y = 0,
 * the peened surface):
 *
 *   block:
 *     mode: plane               # plane (strain) or axisym (default plane)
 *     size: [60 mm, 40 mm]      # width and thickness (required)
 *     thickness: 1 mm           # plane: the slab's out-of-plane extent
 *                               # (default 1 mm); axisym: not read
 *     element: 0.5 mm           # as in 3D
 *     fine: 20 mm               # fine region along x (default: all)
 *     fine_depth, ratio, max_element   as in 3D
 *     bc: {xmin, xmax, bottom, top}    fixed | normal | free (defaults
 *                               normal, normal, fixed, free)
 *
 * plane: x from -width/2 to width/2, the fine region centred; axisym: x
 * is the radius r from 0 (the axis) to width, the fine region from the
 * axis.  *axisym: 1 for axisym; *thick: the plane thickness.  DEM_EINPUT
 * naming the key. */
int dem_scene_block2(dem_scene_t *s, dem_mesh2_t *m, int *axisym, double *thick,
		     dem_error_t *e);

#endif
