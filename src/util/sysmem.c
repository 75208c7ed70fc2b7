/* sysmem.c -- how much memory the machine can give us.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Four limits can stop an allocation, and the smallest one decides:
 *   - MemAvailable from /proc/meminfo (Linux 3.14+: the kernel's estimate of
 *     memory available without swapping), else the physical pages
 *     available from sysconf;
 *   - RLIMIT_AS and RLIMIT_DATA (`ulimit -v`, `ulimit -d`), taken whole:
 *     the estimate they are held against is the run's peak, which dwarfs
 *     what the process holds before it;
 *   - the cgroup (v2) the process runs in: memory.max less memory.current,
 *     read from /sys/fs/cgroup + the path in /proc/self/cgroup.
 * Figures are bytes; 0 means unknown.
 */
#include <config.h>

#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "radiosity/base.h"
#include "util/status.h"

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

/* One number from a cgroup file ("max" and absent files give 0). */
static double cgroup_value(const char *dir, const char *name)
{
    char path[4096 + 64];
    snprintf(path, sizeof path, "/sys/fs/cgroup%s/%s", dir, name);
    FILE *f = fopen(path, "r");
    unsigned long long v = 0;
    if (!f)
        return 0;
    if (fscanf(f, "%llu", &v) != 1)
        v = 0;
    fclose(f);
    return (double)v;
}

/* memory.max - memory.current of this process's cgroup v2, or 0. */
static double cgroup_room(void)
{
    FILE *f = fopen("/proc/self/cgroup", "r");
    char line[4096];
    double room = 0;
    if (!f)
        return 0;
    while (fgets(line, sizeof line, f)) {
        if (strncmp(line, "0::", 3) != 0)
            continue; /* the v2 hierarchy is "0::PATH" */
        line[strcspn(line, "\n")] = '\0';
        const char *dir = strcmp(line + 3, "/") == 0 ? "" : line + 3;
        double max = cgroup_value(dir, "memory.max");
        if (max > 0) {
            double cur = cgroup_value(dir, "memory.current");
            room = max > cur ? max - cur : 1;
        }
        break;
    }
    fclose(f);
    return room;
}

static double smaller(double a, double b)
{
    if (a <= 0)
        return b;
    if (b <= 0)
        return a;
    return a < b ? a : b;
}

double rad_memory_limit(void)
{
    double have = rad_memory_available();
    const int which[] = {RLIMIT_AS, RLIMIT_DATA};
    for (int k = 0; k < 2; k++) {
        struct rlimit rl;
        if (getrlimit(which[k], &rl) == 0 && rl.rlim_cur != RLIM_INFINITY)
            have = smaller(have, (double)rl.rlim_cur);
    }
    return smaller(have, cgroup_room());
}

rad_status rad_memory_check(double need, const char *what, double *have, rad_error *err)
{
    double limit = rad_memory_limit();
    if (have)
        *have = limit;
    if (limit > 0 && need > limit)
        return radi_fail(err, RAD_ERR_TOOBIG,
                        "%s need %.0f MiB, but only %.0f MiB are available (the least of "
                        "free memory, the process limits and the cgroup's); use a coarser "
                        "`mesh`",
                        what, need / 1048576.0, limit / 1048576.0);
    return RAD_OK;
}
