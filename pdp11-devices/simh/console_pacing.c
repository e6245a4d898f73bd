/* console_pacing.c: deterministic polling of the console keyboard (DL11 TTI).

   The DL11's registers stay SIMH's own (pdp11_stddev.c: 177560 RCSR, 177562
   RBUF). Only the unit's service routine is replaced, at start-up, by this one.
   Stock SIMH paces it from the clock's wall-calibrated tmr_poll, so when a
   typed character lands depended on the host; and a character arriving before
   the program had read the previous one overwrote it.

   Here the keyboard is polled every RATE/60 instructions (once per simulated
   tick) while nothing is arriving and every RATE/960 instructions (a 9600-baud
   line) while characters are, so a scripted run sees the same input at the same
   instruction counts. Characters that arrive while RBUF still holds an unread
   one wait in a FIFO (4096) instead of being lost: pasted text is delivered at
   the program's own pace. The keyboard is polled even then, so ^E (SIMH's stop
   key) always works. A nonzero TTI TIME register overrides the slow interval,
   as in stock SIMH. */
#include "devices.h"

extern int32 int_req[IPL_HLVL];
extern int32 tti_csr;
extern UNIT tti_unit;
extern int32 tmr_poll;

#define FIFO_SIZE 4096
#define FAST_PER_S 960

static int32 fifo[FIFO_SIZE];
static int fifo_head, fifo_count;
static int32 fast_acc;

static int32 slow_interval (UNIT *uptr)
{
    return KBD_WAIT (uptr->wait, tmr_poll);
}

static t_stat console_poll_svc (UNIT *uptr)
{
    int32 c = sim_poll_kbd ();
    int busy = 0;
    if (c >= SCPE_KFLAG) {
        if (fifo_count < FIFO_SIZE) {
            fifo[(fifo_head + fifo_count) % FIFO_SIZE] = c;
            fifo_count++;
        }
        busy = 1;
    } else if (c != SCPE_OK) {                   /* ^E and errors: as stock SIMH */
        sim_activate (uptr, slow_interval (uptr));
        return c;
    }
    if (fifo_count > 0 && (tti_csr & CSR_DONE) == 0) {
        c = fifo[fifo_head];
        fifo_head = (fifo_head + 1) % FIFO_SIZE;
        fifo_count--;
        uptr->buf = (c & SCPE_BREAK) ? 0 : sim_tt_inpcvt (c, TT_GET_MODE (uptr->flags));
        uptr->pos = uptr->pos + 1;
        tti_csr |= CSR_DONE;
        if (tti_csr & CSR_IE)
            SET_INT (TTI);
        busy = 1;
    }
    if (fifo_count > 0)
        busy = 1;
    sim_activate (uptr, busy ? clock_share (FAST_PER_S, &fast_acc) : slow_interval (uptr));
    return SCPE_OK;
}

void console_pacing_install (void)
{
    tti_unit.action = &console_poll_svc;
}

void console_pacing_rate_changed (int32 old_rate)
{
    fast_acc = 0;
}
