/* ckpt.h - the checkpoint block of the explicit engines (explicit.c,
 * explicit2d.c), private to libdem.  A block is the engine's header (a
 * struct zeroed before filling, so that it compares and checksums whole;
 * its first 8 bytes a magic), then each state item as its size (uint64)
 * and bytes, then a CRC-32 of everything before it; native byte order.
 * The engine lists its items in one table (name, address, size), the same
 * table for writing and reading, and checks the header itself.
 */
#ifndef DEM_FE_CKPT_H
#define DEM_FE_CKPT_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "core/error.h"
#include "fe/material.h"

typedef struct dem_ckpt_item {
	const char *name;
	void *p;
	size_t size;
} dem_ckpt_item_t;

/* CRC-32 c continued over n bytes at p (c = 0 to start). */
uint32_t dem_ckpt_crc(uint32_t c, const void *p, size_t n);

/* The checksum of what a material's results depend on (its moduli,
 * density, flags, curve and laws), for the header. */
uint32_t dem_ckpt_mat_crc(const dem_mat_t *a);

/* Write the header (hsize bytes), the n items and the checksum to f.
 * DEM_EIO for a write error. */
int dem_ckpt_write(FILE *f, const void *head, size_t hsize, const dem_ckpt_item_t *it, int n,
		   dem_error_t *e);

/* Read the header into head (hsize bytes), the caller to check it:
 * DEM_EINPUT ("truncated") when there is none. */
int dem_ckpt_read_head(FILE *f, void *head, size_t hsize, dem_error_t *e);

/* After the checked header: read the n items into place and check the
 * sizes and the checksum (over the header too).  DEM_EINPUT for a
 * truncated or corrupt block, or an item of another size. */
int dem_ckpt_read_items(FILE *f, const void *head, size_t hsize, const dem_ckpt_item_t *it, int n,
			dem_error_t *e);

#endif
