/* gauss.c -- the public accessors of the Gauss-Legendre table
 * (gausstab.h: the values, their source and their digits).
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 */
#include <config.h>

#include "ff/gausstab.h"
#include "radiosity/formfactor.h"

const double *rad_gauss_nodes(int k)
{
    if (k < 1 || k > RAD_GAUSS_MAX)
        return NULL;
    return gl_nodes(k);
}

const double *rad_gauss_weights(int k)
{
    if (k < 1 || k > RAD_GAUSS_MAX)
        return NULL;
    return gl_weights(k);
}
