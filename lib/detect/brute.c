/* brute.c - brute-force contact detection: every one of the N(N-1)/2 pairs
 * is tested.  O(N^2) time, no extra memory; the reference every other
 * algorithm is tested against (DESIGN.md, "Verification references").
 */
#include "detect/algo.h"

int dem_detect_brute(const dem_boxes_t *b, dem_pairs_t *out,
		     dem_detect_stats_t *st)
{
	size_t n = b->n;

	for (size_t i = 0; i + 1 < n; i++) {
		for (size_t j = i + 1; j < n; j++)
			if (dem_boxes_overlap(b, i, j))
				dem_pairs_push(out, (uint32_t)i, (uint32_t)j);
		if (out->nomem)
			return DEM_EIO;
	}
	if (st && n > 1)
		st->checks += n * (n - 1) / 2;
	return out->nomem ? DEM_EIO : DEM_OK;
}
