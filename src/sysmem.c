/* sysmem.c -- how much memory the machine can give us.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * MemAvailable from /proc/meminfo (Linux 3.14+: the kernel's estimate of
 * memory available without swapping), else the physical pages available
 * from sysconf.  Returns bytes, or 0 when unknown.
 */
#include <config.h>

#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "radiosity.h"

double rad_memory_available(void)
{
    FILE *f = fopen("/proc/meminfo", "r");
    char line[256];
    if (f) {
        while (fgets(line, sizeof line, f)) {
            unsigned long long kb;
            if (sscanf(line, "MemAvailable: %llu kB", &kb) == 1) {
                fclose(f);
                return 1024.0 * (double)kb;
            }
        }
        fclose(f);
    }
    long pages = sysconf(_SC_AVPHYS_PAGES), size = sysconf(_SC_PAGESIZE);
    return pages > 0 && size > 0 ? (double)pages * (double)size : 0.0;
}
