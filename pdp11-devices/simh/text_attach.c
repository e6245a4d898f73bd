/* text_attach.c: ATTACH and DETACH for the devices that write text to a file
   (PLANT's trace, LAB's stream): the file is written from its start (an
   existing one is truncated; a FIFO waits for its reader), a failure says
   which device, which file and why, and leaves the unit detached. */
#include "devices.h"

#include <errno.h>

t_stat device_attach_text (UNIT *uptr, char *cptr, const char *what)
{
    FILE *f;
    char *name;
    if ((f = fopen (cptr, "w")) == NULL) {
        printf ("%s %s: %s\n", what, cptr, strerror (errno));
        return SCPE_OPENERR;
    }
    if ((name = (char *) malloc (strlen (cptr) + 1)) == NULL) {
        fclose (f);
        return SCPE_MEM;
    }
    strcpy (name, cptr);
    uptr->filename = name;
    uptr->fileref = f;
    uptr->flags |= UNIT_ATT;
    return SCPE_OK;
}

void device_detach_text (UNIT *uptr)
{
    fclose (uptr->fileref);
    free (uptr->filename);
    uptr->fileref = NULL;
    uptr->filename = NULL;
    uptr->flags &= ~UNIT_ATT;
}
