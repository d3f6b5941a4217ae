/* ckpt.c - the checkpoint block of the explicit engines (see ckpt.h). */
#include "fe/ckpt.h"

#include <zlib.h>

uint32_t dem_ckpt_crc(uint32_t c, const void *p, size_t n)
{
	const Bytef *b = p;
	uLong u = c;
	while (n > 0) {
		uInt k = n > (1u << 30) ? 1u << 30 : (uInt)n;
		u = crc32(u, b, k);
		b += k, n -= k;
	}
	return (uint32_t)u;
}

uint32_t dem_ckpt_mat_crc(const dem_mat_t *a)
{
	double mp[7] = { a->E, a->nu, a->rho, (double)a->flags, (double)a->nhard, a->rate_m, a->rate_ref };
	uint32_t c = dem_ckpt_crc(0, mp, sizeof mp);
	if (a->nhard > 0) {
		c = dem_ckpt_crc(c, a->hep, (size_t)a->nhard * sizeof *a->hep);
		c = dem_ckpt_crc(c, a->hsy, (size_t)a->nhard * sizeof *a->hsy);
	}
	if (a->flags & DEM_MAT_GENERAL) {
		/* the laws beyond the piecewise linear curve (linear and table
		 * materials keep the checksum of earlier checkpoints) */
		double gp[11 + 2 * DEM_MAT_NKIN] = {
			(double)a->law, a->voce_Q, a->voce_b, a->voce_H, a->jc_A, a->jc_B, a->jc_n,
			(double)a->rate_law, a->cs_D, a->cs_ip, a->jc_C
		};
		for (int i = 0; i < a->nkin; i++) {
			gp[11 + 2 * i] = a->kin_C[i];
			gp[12 + 2 * i] = a->kin_gamma[i];
		}
		c = dem_ckpt_crc(c, gp, sizeof gp);
	}
	return c;
}

int dem_ckpt_write(FILE *f, const void *head, size_t hsize, const dem_ckpt_item_t *it, int n,
		   dem_error_t *e)
{
	uint32_t c = dem_ckpt_crc(0, head, hsize);
	int bad = fwrite(head, hsize, 1, f) != 1;
	for (int i = 0; i < n && !bad; i++) {
		uint64_t sz = it[i].size;
		c = dem_ckpt_crc(c, &sz, sizeof sz);
		c = dem_ckpt_crc(c, it[i].p, it[i].size);
		bad = fwrite(&sz, sizeof sz, 1, f) != 1 || fwrite(it[i].p, 1, it[i].size, f) != it[i].size;
	}
	if (bad || fwrite(&c, sizeof c, 1, f) != 1)
		return dem_error_set(e, DEM_EIO, "checkpoint: write error");
	return DEM_OK;
}

int dem_ckpt_read_head(FILE *f, void *head, size_t hsize, dem_error_t *e)
{
	if (fread(head, hsize, 1, f) != 1)
		return dem_error_set(e, DEM_EINPUT, "checkpoint: truncated (no model header)");
	return DEM_OK;
}

int dem_ckpt_read_items(FILE *f, const void *head, size_t hsize, const dem_ckpt_item_t *it, int n,
			dem_error_t *e)
{
	uint32_t c = dem_ckpt_crc(0, head, hsize);
	for (int i = 0; i < n; i++) {
		uint64_t sz;
		if (fread(&sz, sizeof sz, 1, f) != 1)
			return dem_error_set(e, DEM_EINPUT, "checkpoint: truncated (at '%s')", it[i].name);
		if (sz != it[i].size)
			return dem_error_set(e, DEM_EINPUT, "checkpoint: '%s' has %llu bytes, expected %zu",
					     it[i].name, (unsigned long long)sz, it[i].size);
		if (fread(it[i].p, 1, it[i].size, f) != it[i].size)
			return dem_error_set(e, DEM_EINPUT, "checkpoint: truncated (in '%s')", it[i].name);
		c = dem_ckpt_crc(c, &sz, sizeof sz);
		c = dem_ckpt_crc(c, it[i].p, it[i].size);
	}
	uint32_t crc;
	if (fread(&crc, sizeof crc, 1, f) != 1)
		return dem_error_set(e, DEM_EINPUT, "checkpoint: truncated (no checksum)");
	if (crc != c)
		return dem_error_set(e, DEM_EINPUT, "checkpoint: corrupt (checksum mismatch)");
	return DEM_OK;
}
