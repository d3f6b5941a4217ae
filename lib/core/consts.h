/* consts.h - mathematical constants (strict C11 has no M_PI). */
#ifndef DEM_CORE_CONSTS_H
#define DEM_CORE_CONSTS_H

#define DEM_PI 3.14159265358979323846

#endif
