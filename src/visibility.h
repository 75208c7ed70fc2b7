/* visibility.h -- (being written) */
#ifndef RAD_VISIBILITY_H
#define RAD_VISIBILITY_H
#endif
