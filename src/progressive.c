/* progressive.c -- (being written) */
#include <config.h>

#include "radiosity.h"
#include "status.h"

rad_status rad_solve_progressive(const rad_mesh *mesh, const double *F, const double *rho,
                                 const double *E, const rad_solve_options *opt, double *B,
                                 rad_solve_report *report, rad_error *err)
{
    (void)mesh, (void)F, (void)rho, (void)E, (void)opt, (void)B, (void)report;
    return rad_fail(err, RAD_ERR_INVALID, "progressive refinement is not built yet");
}
