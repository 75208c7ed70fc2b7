/* main.c -- the radiosity program's entry point.
 *
 * Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
 *
 * Everything is in cli.c, which radiosity-mpi shares: this file only
 * gives the serial program its main.
 */
#include <config.h>

#include "cli/cli.h"

int main(int argc, char **argv)
{
    return cli_main(argc, argv);
}
