/* occlusion.c -- (being written) */
#include <config.h>
