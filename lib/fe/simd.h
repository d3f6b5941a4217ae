/* simd.h - the vector conventions of the batched kernels of lib/fe
 * (hex8.c, material.c, explicit.c; internal).
 *
 * A batch is NB lanes, one element or material point each, held in a
 * vector of NB doubles (GCC/Clang vector extension), so every operation
 * runs across the batch in SIMD registers whatever the target's width.  On
 * x86-64 with GCC the kernels marked SIMD_CLONES are also compiled for
 * AVX2 (x86-64-v3) and the copy to run is chosen at load time; define
 * DEM_NO_SIMD_CLONES to build the default copy only. */
#ifndef DEM_FE_SIMD_H
#define DEM_FE_SIMD_H

#include <string.h>

#include "fe/material.h"

#define NB DEM_MAT_NB

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) && \
    !defined(DEM_NO_SIMD_CLONES)
#define SIMD_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define SIMD_CLONES
#endif

typedef double vec __attribute__((vector_size(NB * sizeof(double))));
typedef long long lvec __attribute__((vector_size(NB * sizeof(double))));  /* masks */

/* (macros: passing wide vectors by value would tie us to an ABI) */
#define VLOAD(v, p) memcpy(&(v), (p), sizeof(vec))
#define VSTORE(p, v) memcpy((p), &(v), sizeof(vec))

#endif
