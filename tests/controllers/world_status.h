/* world_status.h: the lock-step coordinator's status (quantum.h's
   ls_world_status) as a string, for the C tests that look into it. */
#ifndef WORLD_STATUS_H
#define WORLD_STATUS_H

#include <stdio.h>
#include <stdlib.h>

#include "quantum.h"

/* The status after quantum k; the caller free()s it. */
static char *world_status (const ls_world *w, uint64_t k)
{
    char *text = NULL;
    size_t size = 0;
    FILE *f = open_memstream (&text, &size);
    ls_world_status (f, w, k);
    fclose (f);
    return text;
}

#endif
