/* share.h - files of the toolkit's data directory (share/), such as the
 * material and shot libraries that a scene pulls in with "use: NAME".
 *
 * The data directory is the first of:
 *   1. $DEM_SHARE, when set and not empty (the user's explicit choice:
 *      nothing else is searched);
 *   2. the share/ folder of the nearest ancestor of the running program's
 *      directory that has share/FOLDER (bin/ and share/ side by side in the
 *      source tree, and build/san/bin three levels down);
 *   3. DEM_DATADIR, compiled in (the Makefile's DATADIR).
 */
#ifndef DEM_CORE_SHARE_H
#define DEM_CORE_SHARE_H

#include <stddef.h>

/* Find FOLDER/FILE ("materials", "al7075.yaml") in the data directory.
 * Returns 0 with *path (malloc'd) naming an existing regular file; 1 when
 * there is none, with a description of the folders searched and how they
 * were chosen in tried ("/x/share/materials (from DEM_SHARE)"); -1 when
 * out of memory. */
int dem_share_find(const char *folder, const char *file, char **path,
		   char *tried, size_t triedlen);

#endif
