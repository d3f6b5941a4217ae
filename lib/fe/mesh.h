/* fe/mesh.h - the structured hexahedral mesh moved to mesh/mesh.h, below
 * both the FE stages and the streams that write it; this name stays for
 * programs written against it. */
#ifndef DEM_FE_MESH_H
#define DEM_FE_MESH_H

#include "mesh/mesh.h"

#endif
