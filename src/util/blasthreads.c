/* blasthreads.c -- keep OpenBLAS's idle threads off the cores at start-up.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * OpenBLAS (Debian's pthread build, which serves liblapack.so.3) starts
 * its worker threads when the library is loaded, and each spins for about
 * 2^28 cycles (a tenth of a second, its THREAD_TIMEOUT) before it sleeps.
 * A program that starts computing at once -- the form-factor fill of a
 * small scene takes a few milliseconds on OpenMP threads -- then shares
 * its cores with them: on a 2-core machine one run in four of the 7x7 cube
 * took 70 ms instead of 3.  OpenBLAS's own blas_thread_shutdown_ (its fork
 * handler) stops them, and OpenBLAS starts them again at its next threaded
 * call (after which they spin again: `radiosity sweep` parks them before
 * each timed fill).  The reference is weak: with another BLAS the symbol
 * is absent and nothing happens.
 */
#include <config.h>

#include "util/lapack.h"

extern int blas_thread_shutdown_(void) __attribute__((weak));

void radi_blas_park_threads(void)
{
    if (blas_thread_shutdown_)
        blas_thread_shutdown_();
}
