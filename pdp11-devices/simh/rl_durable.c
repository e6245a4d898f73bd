/* rl_durable.c: RL02 writes reach the host's disk before the FORTH sees them done.

   The RLV12 and its drives stay SIMH's own (pdp11_rl.c: 174400 RLCS, 174402
   RLBA, 174404 RLDA, 174406 RLMP; the FORTH's driver is forth/kernel/disk.fs).
   Only each RL unit's service routine is wrapped, at start-up, by this one.

   Why: stock SIMH 3.8.1 writes a sector with fwrite() into the image's stdio
   buffer and sets the controller's done bit at once; the bytes reach the file
   only at the next fseek of a later transfer, when the machine stops at sim>,
   or at DETACH. A FLUSH that answered " ok" was therefore lost when the
   simulator was killed (kill -9, a crash, the host's power) right after it.

   How: SIMH runs a transfer in the unit's service routine (rl_svc), which reads
   the function from RLCS and sets CSR DONE (CRDY) before returning. The wrapper
   calls rl_svc and, when the function was WRITE DATA (5) and it succeeded,
   fflush()es the unit's FILE and fsync()s its descriptor before returning. The
   CPU executes no instruction in between, so when the FORTH's driver sees CRDY
   the block is in the image file and on the host's storage. Reads, seeks and
   status requests are not touched.

   If the flush or the fsync fails (disk full, I/O error) the transfer is
   reported to the PDP-11 as failed: RLCS bits 15 (error) and 14 (drive error)
   are set and the drive status gets bit 15 (write data error), so the FORTH
   prints "RL0 block n write failed: ... drive-error" and THROWs -34 instead
   of answering " ok"; SIMH prints the host's reason ("RL write-through: ...").

   Cost: one fsync per block written (the FORTH moves a 1024-byte block in one
   transfer). It costs host time only; simulated time (the instruction count,
   1344 instructions for FLUSH of one block) is unchanged, so transcripts and
   traces are the same. make bench-disk prints the host time: 140-550 us per
   FLUSHed block on the project's shared ext4 host (as busy as its disk),
   against 25-50 us without the write-through (a build with it removed): the
   fsync is nearly all of it.
   Proof: make soak-disk (harness/soak/disk_soak.py) kills the simulator with
   SIGKILL after FLUSH, 100 times, and finds every flushed block. */
#include <errno.h>
#include <string.h>
#include <unistd.h>
#include "devices.h"

extern DEVICE rl_dev;
extern int32 rlcs;

#define RLCS_FUNC(csr) (((csr) >> 1) & 07)
#define RL_WRITE_DATA  5
#define RLCS_ERR_DRE   0140000          /* error summary + drive error */
#define RLDS_WDE       0100000          /* drive status: write data error */
#define RL_STAT        u4               /* pdp11_rl.c keeps the drive status here (STAT) */

static t_stat (*stock_rl_svc) (UNIT *uptr);

/* 0 when the unit's written data are on the host's storage, else errno. */
static int write_through (UNIT *uptr)
{
    if (fflush (uptr->fileref) != 0)
        return errno ? errno : EIO;
    if (fsync (fileno (uptr->fileref)) != 0)
        return errno;
    return 0;
}

static t_stat rl_durable_svc (UNIT *uptr)
{
    int writing = RLCS_FUNC (rlcs) == RL_WRITE_DATA;
    t_stat r = stock_rl_svc (uptr);
    int err;
    if (!writing || r != SCPE_OK || (uptr->flags & UNIT_ATT) == 0 || (rlcs & 0100000))
        return r;
    err = write_through (uptr);
    if (err) {
        fprintf (stderr, "\r\nRL write-through: %s: %s\r\n", uptr->filename, strerror (err));
        clearerr (uptr->fileref);
        rlcs |= RLCS_ERR_DRE;
        uptr->RL_STAT |= RLDS_WDE;
    }
    return r;
}

void rl_durable_install (void)
{
    stock_rl_svc = rl_dev.units[0].action;
    for (uint32 i = 0; i < rl_dev.numunits; i++)
        rl_dev.units[i].action = &rl_durable_svc;
}
