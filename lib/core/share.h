/* share.h - files of the toolkit's data directory (share/), such as the
 * material and shot libraries that a scene pulls in with "use: NAME".
 *
 * The data directory is the first of:
 *   1. $DEM_DATA, when set and not empty (the user's explicit choice:
 *      nothing else is searched);
 *   2. the share/ folder of the source tree the running program was built
 *      in: the nearest ancestor of its directory that has share/FOLDER and
 *      lib/core/share.h (bin/ at the top of the tree, build/san/bin three
 *      levels down); an installed program has no such ancestor;
 *   3. DEM_DATADIR, compiled in (the Makefile's pkgdatadir,
 *      $(datadir)/dem, where make install puts share/).
 */
#ifndef DEM_CORE_SHARE_H
#define DEM_CORE_SHARE_H

#include <stddef.h>

/* Find FOLDER/FILE ("materials", "al7075.yaml") in the data directory.
 * Returns 0 with *path (malloc'd) naming an existing regular file; 1 when
 * there is none, with a description of the folders searched and how they
 * were chosen in tried ("/x/share/materials (from DEM_DATA)"); -1 when
 * out of memory. */
int dem_share_find(const char *folder, const char *file, char **path,
		   char *tried, size_t triedlen);

#endif
