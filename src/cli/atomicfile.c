/* atomicfile.c -- output files that appear whole or not at all, and never
 * destroy what they did not create.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * What a target path names decides how it is written (radiosity-files(5),
 * HOW OUTPUTS ARE WRITTEN):
 *
 *   "-", /dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N
 *        the descriptor the caller already holds, written directly (dup);
 *   a symbolic link
 *        followed, hop by hop (at most RAD_AFILE_MAX_HOPS), to the path it
 *        names; that path is then treated as below and the link is kept;
 *   a character or block device, a FIFO, a socket
 *        opened and written directly: a device is never replaced by a
 *        regular file (as root, rename(2) would happily do so);
 *   a directory
 *        refused;
 *   a regular file, or nothing
 *        written to a temporary "NAME.tmpXXXXXX" in the same directory and
 *        renamed over NAME on commit, keeping an existing file's permission
 *        bits; a failed or interrupted run leaves NAME as it was.
 */
#include <config.h>

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/atomicfile.h"
#include "util/util.h"

#define RAD_AFILE_MAX_HOPS 40 /* as the kernel's own limit on link chains */

/* The descriptor a path stands for when it names one the process holds
 * ("/dev/stdout", "/dev/fd/3", ...), or -1. */
static int held_descriptor(const char *path)
{
    static const char *const prefixes[] = {"/dev/fd/", "/proc/self/fd/"};
    if (strcmp(path, "-") == 0 || strcmp(path, "/dev/stdout") == 0)
        return STDOUT_FILENO;
    if (strcmp(path, "/dev/stderr") == 0)
        return STDERR_FILENO;
    for (size_t k = 0; k < sizeof prefixes / sizeof *prefixes; k++) {
        size_t len = strlen(prefixes[k]);
        if (strncmp(path, prefixes[k], len) == 0 && path[len]) {
            char *end;
            long fd = strtol(path + len, &end, 10);
            if (*end == '\0' && fd >= 0 && fd <= INT_MAX)
                return (int)fd;
        }
    }
    return -1;
}

/* Follow symbolic links from path to the name that is not one (which may
 * not exist yet).  Returns a malloc'd path, or NULL with errno set. */
static char *follow_links(const char *path)
{
    char *cur = strdup(path);
    for (int hop = 0; cur && hop <= RAD_AFILE_MAX_HOPS; hop++) {
        struct stat st;
        if (lstat(cur, &st) != 0 || !S_ISLNK(st.st_mode))
            return cur; /* absent, or not a link: the target */
        char link[PATH_MAX];
        ssize_t k = readlink(cur, link, sizeof link - 1);
        if (k < 0) {
            free(cur);
            return NULL;
        }
        link[k] = '\0';
        const char *slash = strrchr(cur, '/');
        size_t dir = (link[0] != '/' && slash) ? (size_t)(slash - cur) + 1 : 0;
        char *next = malloc(dir + (size_t)k + 1);
        if (next) {
            memcpy(next, cur, dir); /* a relative link is relative to its directory */
            memcpy(next + dir, link, (size_t)k + 1);
        }
        free(cur);
        cur = next;
    }
    if (cur) {
        free(cur);
        errno = ELOOP;
    }
    return NULL;
}

/* The message first: path may be f->user_path, which the abort frees. */
static rad_status fail_errno(rad_afile *f, rad_error *err, const char *path, int e)
{
    rad_status st = radi_fail(err, e == ENOMEM ? RAD_ERR_NOMEM : RAD_ERR_IO, "%s: %s", path,
                             strerror(e));
    radi_afile_abort(f);
    return st;
}

/* Write straight into fd (a descriptor of ours, or one we opened). */
static rad_status open_direct(rad_afile *f, int fd, const char *path, rad_error *err)
{
    f->fp = fdopen(fd, "w");
    if (!f->fp) {
        int e = errno;
        close(fd);
        return fail_errno(f, err, path, e);
    }
    f->direct = 1;
    return RAD_OK;
}

/* A temporary beside target, so rename(2) stays on one file system. */
static rad_status open_temporary(rad_afile *f, const struct stat *old, rad_error *err)
{
    size_t len = strlen(f->path);
    f->tmp = malloc(len + 16);
    if (!f->tmp)
        return fail_errno(f, err, f->user_path, ENOMEM);
    snprintf(f->tmp, len + 16, "%s.tmpXXXXXX", f->path);
    int fd = mkstemp(f->tmp);
    if (fd < 0) {
        int e = errno;
        free(f->tmp);
        f->tmp = NULL;
        return fail_errno(f, err, f->user_path, e);
    }
    mode_t mode;
    if (old) {
        mode = old->st_mode & 07777;
    } else {
        mode_t mask = umask(022); /* read the umask: mkstemp creates 0600 */
        umask(mask);
        mode = 0666 & ~mask;
    }
    (void)fchmod(fd, mode);
    f->fp = fdopen(fd, "w");
    if (!f->fp) {
        int e = errno;
        close(fd);
        return fail_errno(f, err, f->user_path, e);
    }
    return RAD_OK;
}

rad_status radi_afile_open(rad_afile *f, const char *path, rad_error *err)
{
    memset(f, 0, sizeof *f);
    f->user_path = strdup(path);
    if (!f->user_path)
        return fail_errno(f, err, path, ENOMEM);
    int held = held_descriptor(path);
    if (held >= 0) {
        fflush(NULL); /* what stdio holds for that descriptor goes first */
        int fd = dup(held);
        if (fd < 0)
            return fail_errno(f, err, path, errno);
        return open_direct(f, fd, path, err);
    }
    f->path = follow_links(path);
    if (!f->path)
        return fail_errno(f, err, path, errno);
    struct stat st;
    if (stat(f->path, &st) != 0) {
        if (errno != ENOENT)
            return fail_errno(f, err, path, errno);
        return open_temporary(f, NULL, err);
    }
    if (S_ISDIR(st.st_mode))
        return fail_errno(f, err, path, EISDIR);
    if (S_ISREG(st.st_mode))
        return open_temporary(f, &st, err);
    int fd = open(f->path, O_WRONLY | O_NOCTTY | O_CLOEXEC); /* device, FIFO: as it is */
    if (fd < 0)
        return fail_errno(f, err, path, errno);
    return open_direct(f, fd, path, err);
}

rad_status radi_afile_check(const char *path, rad_error *err)
{
    if (held_descriptor(path) >= 0)
        return RAD_OK;
    char *target = follow_links(path);
    if (!target)
        return radi_fail(err, RAD_ERR_IO, "%s: %s", path, strerror(errno));
    struct stat st;
    rad_status rs = RAD_OK;
    if (stat(target, &st) == 0) {
        if (S_ISDIR(st.st_mode))
            rs = radi_fail(err, RAD_ERR_IO, "%s: %s", path, strerror(EISDIR));
        else if (!S_ISREG(st.st_mode) && access(target, W_OK) != 0)
            rs = radi_fail(err, RAD_ERR_IO, "%s: %s", path, strerror(errno));
    }
    if (rs == RAD_OK && (stat(target, &st) != 0 || S_ISREG(st.st_mode))) {
        /* replaced by rename: its directory must exist and take new files */
        char *slash = strrchr(target, '/');
        const char *dir = ".";
        if (slash == target)
            dir = "/";
        else if (slash) {
            *slash = '\0';
            dir = target;
        }
        if (stat(dir, &st) != 0)
            rs = radi_fail(err, RAD_ERR_IO, "%s: %s", path, strerror(errno));
        else if (!S_ISDIR(st.st_mode))
            rs = radi_fail(err, RAD_ERR_IO, "%s: %s", path, strerror(ENOTDIR));
        else if (access(dir, W_OK | X_OK) != 0)
            rs = radi_fail(err, RAD_ERR_IO, "%s: %s", path, strerror(errno));
    }
    free(target);
    return rs;
}

int radi_afile_is_direct(const char *path)
{
    if (held_descriptor(path) >= 0)
        return 1;
    char *target = follow_links(path);
    struct stat st;
    int direct = target && stat(target, &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
    free(target);
    return direct;
}

/* Flush, sync (a temporary) and close f->fp: 0, or the errno. */
static int finish(rad_afile *f)
{
    int bad = fflush(f->fp) != 0 || ferror(f->fp);
    int e = bad ? (errno ? errno : EIO) : 0;
    if (!bad && f->tmp && fsync(fileno(f->fp)) != 0) {
        bad = 1;
        e = errno;
    }
    if (fclose(f->fp) != 0 && !bad) {
        bad = 1;
        e = errno;
    }
    f->fp = NULL;
    return bad ? e : 0;
}

rad_status radi_afile_close(rad_afile *f, rad_error *err)
{
    const int e = f->fp ? finish(f) : 0;
    if (e) {
        rad_status st = radi_fail(err, RAD_ERR_IO, "%s: %s", f->user_path, strerror(e));
        radi_afile_abort(f);
        return st;
    }
    return RAD_OK;
}

rad_status radi_afile_commit(rad_afile *f, rad_error *err)
{
    int e = f->fp ? finish(f) : 0; /* closed already by radi_afile_close */
    int bad = e != 0;
    if (!bad && f->tmp && rename(f->tmp, f->path) != 0) {
        bad = 1;
        e = errno;
    }
    rad_status st = RAD_OK;
    if (bad) {
        st = radi_fail(err, RAD_ERR_IO, "%s: %s", f->user_path, strerror(e));
    } else {
        free(f->tmp); /* renamed: nothing left to remove */
        f->tmp = NULL;
    }
    radi_afile_abort(f);
    return st;
}

void radi_afile_abort(rad_afile *f)
{
    if (f->fp)
        fclose(f->fp);
    if (f->tmp)
        unlink(f->tmp);
    free(f->tmp);
    free(f->path);
    free(f->user_path);
    memset(f, 0, sizeof *f);
}
