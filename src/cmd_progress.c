/* cmd_progress.c -- (being written) */
#include <config.h>
#include "cli.h"
int cmd_progress(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    cli_error("progress is not built yet");
    return 1;
}
