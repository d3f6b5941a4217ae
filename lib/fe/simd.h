/* simd.h - the vector conventions of the batched kernels of lib/fe
 * (hex8.c, material.c, explicit.c; internal).
 *
 * A batch is NB lanes, one element or material point each, held in a
 * vector of NB doubles (GCC/Clang vector extension), so every operation
 * runs across the batch in SIMD registers whatever the target's width.  On
 * x86-64 with GCC the kernels marked SIMD_CLONES are also compiled for
 * AVX2 (x86-64-v3) and for AVX-512 (x86-64-v4), and the copy to run is
 * chosen at load time; define DEM_NO_SIMD_CLONES to build the default copy
 * only.  The AVX-512 copy keeps the 4-lane vectors (256-bit registers, the
 * VL encodings, 32 of them instead of 16); on an AMD EPYC of the Zen 4
 * kind the batch kinematics, material update and internal forces run in
 * about half the time of the AVX2 copy (perf samples of fe-bench, one
 * thread, 2026-12-05: 445, 288, 110 against 202, 135, 55).  With -std=c11
 * no multiply-add is contracted and no sum reassociated, so every copy
 * gives the same bits. */
#ifndef DEM_FE_SIMD_H
#define DEM_FE_SIMD_H

#include <string.h>

#include "fe/material.h"

#define NB DEM_MAT_NB

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) && \
    !defined(DEM_NO_SIMD_CLONES)
#define SIMD_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define SIMD_CLONES
#endif

typedef double vec __attribute__((vector_size(NB * sizeof(double))));
typedef long long lvec __attribute__((vector_size(NB * sizeof(double))));  /* masks */

/* (macros: passing wide vectors by value would tie us to an ABI) */
#define VLOAD(v, p) memcpy(&(v), (p), sizeof(vec))
#define VSTORE(p, v) memcpy((p), &(v), sizeof(vec))

#endif
