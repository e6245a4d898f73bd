/* rl_one_writer.c: one simulator at a time writes a disk image.

   The RLV12 and its drives stay SIMH's own (pdp11_rl.c); only the RL device's
   ATTACH and DETACH are wrapped, at start-up, by these.

   Why: each simulator keeps its own FORTH block buffers. Two of them on one
   image (make lab beside make run, both on local/robot.dsk) each FLUSH what
   they hold, and the second silently undoes blocks the first had written.

   How: a read-write ATTACH of an RL unit takes an exclusive flock(2) on the
   image's open file (non-blocking). The kernel holds the lock for the open
   file: it ends when the unit is detached, when SIMH exits, and when the
   process dies in any way (kill -9, a crash), so a lock is never left stale
   and make soak-disk's killed simulators leave nothing behind. The descriptor
   is close-on-exec, so a shell started with SIMH's `!` does not inherit it.
   Beside the image, IMAGE.lock names the holder ("pid N since DATE UTC"): it
   is only information, written after the lock is taken and removed at DETACH;
   one left by a killed simulator means nothing (the next holder rewrites it).

   A second read-write ATTACH of a held image (in another simulator, or on a
   second unit of this one) is refused in one line naming the holder. In the
   startup script (build/pdp11 build/robot.ini, the harness's boot scripts:
   any ATTACH before the first sim> prompt) the simulator then exits with
   status 3 instead of booting the FORTH with no disk; typed at sim> it is an
   error and the unit stays detached.

   ATTACH -R (read-only: `build/pdp11 build/robot.ini -r`, or --read-only in
   the harness) takes no lock and may sit beside a writer: SIMH's RL then
   reports the drive write-locked, and the FORTH's FLUSH answers "RL0 block n
   write not ready: ... write-locked" and keeps the block UPDATEd. */
#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <sys/file.h>
#include <time.h>
#include <unistd.h>
#include "devices.h"

extern DEVICE rl_dev;
extern char *(*sim_vm_read) (char *ptr, int32 size, FILE *stream);
char *read_line (char *ptr, int32 size, FILE *stream);

#define REFUSED_AT_START 3              /* exit status: the startup script's disk is held */
#define HOLDER_MAX 200
#define RL_UNITS 4                      /* pdp11_rl.c's RL_NUMDR */

static t_stat (*stock_rl_attach) (UNIT *uptr, char *cptr);
static t_bool prompt_seen;              /* a command was read at sim>: no longer start-up */
static char *holder_files[RL_UNITS];    /* IMAGE.lock of each unit holding its image */

static char *holder_file_name (const char *image)
{
    char *name = (char *) malloc (strlen (image) + sizeof ".lock");
    if (name != NULL)
        sprintf (name, "%s.lock", image);
    return name;
}

/* Who holds `image`, as its IMAGE.lock says; a fallback when it cannot be read. */
static void read_holder (const char *image, char *holder, size_t n)
{
    char *name = holder_file_name (image);
    FILE *f = name ? fopen (name, "r") : NULL;
    snprintf (holder, n, "another process (%s cannot be read)", name ? name : "its .lock file");
    if (f != NULL) {
        if (fgets (holder, (int) n, f) == NULL)
            snprintf (holder, n, "another process (%s is empty)", name);
        holder[strcspn (holder, "\r\n")] = 0;
        fclose (f);
    }
    free (name);
}

/* IMAGE.lock: "pid N since DATE UTC", written whole (temporary file, rename). */
static char *write_holder (const char *image)
{
    char *name = holder_file_name (image), *tmp;
    char since[40];
    time_t now = time (NULL);
    FILE *f;
    if (name == NULL || (tmp = (char *) malloc (strlen (name) + 16)) == NULL) {
        free (name);
        return NULL;
    }
    sprintf (tmp, "%s.%ld", name, (long) getpid ());
    strftime (since, sizeof since, "%Y-%m-%d %H:%M:%S", gmtime (&now));
    if ((f = fopen (tmp, "w")) != NULL) {
        fprintf (f, "pid %ld since %s UTC\n", (long) getpid (), since);
        if (fclose (f) == 0 && rename (tmp, name) == 0) {
            free (tmp);
            return name;
        }
        remove (tmp);
    }
    free (tmp);                         /* a directory we cannot write: no holder file */
    free (name);
    return NULL;
}

static void forget_holder (int unit)
{
    if (holder_files[unit] != NULL) {
        remove (holder_files[unit]);
        free (holder_files[unit]);
        holder_files[unit] = NULL;
    }
}

static t_stat rl_one_writer_attach (UNIT *uptr, char *cptr)
{
    int unit = (int) (uptr - rl_dev.units), fd;
    char holder[HOLDER_MAX];
    t_stat r = stock_rl_attach (uptr, cptr);
    if (r != SCPE_OK || (uptr->flags & UNIT_RO))
        return r;
    fd = fileno (uptr->fileref);
    fcntl (fd, F_SETFD, FD_CLOEXEC);
    if (flock (fd, LOCK_EX | LOCK_NB) == 0) {
        forget_holder (unit);
        holder_files[unit] = write_holder (cptr);
        return SCPE_OK;
    }
    if (errno != EWOULDBLOCK) {         /* a file system without locks: say so, go on */
        printf ("RL%d: %s cannot be locked (%s): nothing stops a second simulator "
                "writing it\n", unit, cptr, strerror (errno));
        return SCPE_OK;
    }
    read_holder (cptr, holder, sizeof holder);
    detach_unit (uptr);
    printf ("RL%d: %s is in use by %s: one simulator writes an image at a time; leave "
            "that one first, or attach it read-only (ATTACH -R RL%d %s, or "
            "build/pdp11 build/robot.ini -r, or --read-only in the harness)\n",
            unit, cptr, holder, unit, cptr);
    fflush (stdout);
    if (!prompt_seen)                   /* the startup script: do not boot diskless */
        exit (REFUSED_AT_START);
    return SCPE_OPENERR;
}

static t_stat rl_one_writer_detach (UNIT *uptr)
{
    forget_holder ((int) (uptr - rl_dev.units));
    return detach_unit (uptr);          /* closes the file: the lock goes with it */
}

static char *read_at_prompt (char *ptr, int32 size, FILE *stream)
{
    prompt_seen = TRUE;
    return read_line (ptr, size, stream);
}

void rl_one_writer_install (void)
{
    stock_rl_attach = rl_dev.attach;
    rl_dev.attach = &rl_one_writer_attach;
    rl_dev.detach = &rl_one_writer_detach;
    sim_vm_read = &read_at_prompt;
}
