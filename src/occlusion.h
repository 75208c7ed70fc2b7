/* occlusion.h -- (being written) */
#ifndef RAD_OCCLUSION_H
#define RAD_OCCLUSION_H
#endif
