/* atomicfile.c -- output files that appear whole or not at all.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#include <config.h>

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "atomicfile.h"
#include "status.h"

rad_status rad_afile_open(rad_afile *f, const char *path, rad_error *err)
{
    memset(f, 0, sizeof *f);
    if (strcmp(path, "-") == 0) {
        f->fp = stdout;
        return RAD_OK;
    }
    size_t len = strlen(path);
    f->path = strdup(path);
    f->tmp = malloc(len + 16);
    if (!f->path || !f->tmp) {
        rad_afile_abort(f);
        return rad_fail(err, RAD_ERR_NOMEM, "out of memory");
    }
    /* temporary beside the target, so rename(2) stays on one file system */
    snprintf(f->tmp, len + 16, "%s.tmpXXXXXX", path);
    int fd = mkstemp(f->tmp);
    if (fd < 0) {
        int e = errno;
        free(f->tmp);
        f->tmp = NULL;
        rad_afile_abort(f);
        return rad_fail(err, RAD_ERR_IO, "%s: %s", path, strerror(e));
    }
    mode_t mask = umask(022); /* read the umask: mkstemp creates 0600 */
    umask(mask);
    (void)fchmod(fd, 0666 & ~mask);
    f->fp = fdopen(fd, "w");
    if (!f->fp) {
        int e = errno;
        close(fd);
        rad_afile_abort(f);
        return rad_fail(err, RAD_ERR_IO, "%s: %s", path, strerror(e));
    }
    return RAD_OK;
}

rad_status rad_afile_commit(rad_afile *f, rad_error *err)
{
    rad_status st = RAD_OK;
    if (!f->tmp) { /* standard output */
        if (fflush(stdout) != 0 || ferror(stdout))
            st = rad_fail(err, RAD_ERR_IO, "standard output: %s", strerror(errno));
        memset(f, 0, sizeof *f);
        return st;
    }
    int bad = fflush(f->fp) != 0 || ferror(f->fp) || fsync(fileno(f->fp)) != 0;
    int e = errno;
    if (fclose(f->fp) != 0 && !bad) {
        bad = 1;
        e = errno;
    }
    f->fp = NULL;
    if (!bad && rename(f->tmp, f->path) != 0) {
        bad = 1;
        e = errno;
    }
    if (bad) {
        st = rad_fail(err, RAD_ERR_IO, "%s: %s", f->path, strerror(e));
    } else {
        free(f->tmp); /* renamed: nothing left to remove */
        f->tmp = NULL;
    }
    rad_afile_abort(f);
    return st;
}

void rad_afile_abort(rad_afile *f)
{
    if (f->fp && f->fp != stdout)
        fclose(f->fp);
    if (f->tmp)
        unlink(f->tmp);
    free(f->tmp);
    free(f->path);
    memset(f, 0, sizeof *f);
}
