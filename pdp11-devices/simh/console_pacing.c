/* console_pacing.c: deterministic polling of the console keyboard (DL11 TTI),
   and the terminal's side of XON/XOFF flow control.

   The DL11's registers stay SIMH's own (pdp11_stddev.c: 177560 RCSR, 177562
   RBUF, 177564 XCSR, 177566 XBUF). Only the two units' service routines are
   wrapped, at start-up, by the ones here. Stock SIMH paces the keyboard from
   the clock's wall-calibrated tmr_poll, so when a typed character lands
   depended on the host; and a character arriving before the program had read
   the previous one overwrote it.

   Keyboard (TTI): polled every RATE/60 instructions (once per simulated tick)
   while nothing is arriving and every RATE/960 instructions (a 9600-baud line)
   while characters are, so a scripted run sees the same input at the same
   instruction counts. A character read while RBUF still holds an unread one
   waits in a FIFO (4096); a full FIFO reads no more (the rest waits on the
   host's side), so nothing is dropped here.

   Flow control (docs/console.md, "A paste"): the FORTH's receive interrupt
   writes XOFF (DC3, 023) to XBUF when its ring is nearly full and KEY writes
   XON (DC1, 021) when it has drained it, as a host told a paper-tape reader to
   stop and go on. The printer side (TTO) watches XBUF for them: while XOFF
   holds the keyboard is neither read nor delivered (what is typed waits in the
   host's pty and, beyond it, in the harness); XON polls again at once. The
   stock TTO service then prints them as it would (not at all, in its 7-bit
   printable mode), so they never reach the screen.

   ^C from the harness (SIGUSR1): the user's interrupt key jumps the queue, as
   the harness holds it (harness/machine/key_feed.py): at the next poll the
   FIFO is emptied, XOFF is lifted and ^C (003) is put into RBUF with its done
   flag and interrupt request, whatever RBUF held, so the FORTH's receive
   interrupt stops a running word even while a paste is waiting. ^E, SIMH's
   stop key, comes as a signal from the pty and needs no poll.
   A nonzero TTI TIME register overrides the slow interval, as in stock SIMH. */
#include "devices.h"
#include <signal.h>

extern int32 int_req[IPL_HLVL];
extern int32 tti_csr;
extern UNIT tti_unit, tto_unit;
extern int32 tmr_poll;
extern t_stat tto_svc (UNIT *uptr);

#define FIFO_SIZE 4096
#define FAST_PER_S 960
#define DC1 021                                  /* XON */
#define DC3 023                                  /* XOFF */
#define CTRL_C 003

static int32 fifo[FIFO_SIZE];
static int fifo_head, fifo_count;
static int32 fast_acc;
static int xoff;                                 /* the FORTH asked the keyboard to wait */
static volatile sig_atomic_t interrupt_key;      /* ^C from the harness, not yet delivered */

static int32 slow_interval (UNIT *uptr)
{
    return KBD_WAIT (uptr->wait, tmr_poll);
}

static void receive (UNIT *uptr, int32 c)
{
    uptr->buf = (c & SCPE_BREAK) ? 0 : sim_tt_inpcvt (c, TT_GET_MODE (uptr->flags));
    uptr->pos = uptr->pos + 1;
    tti_csr |= CSR_DONE;
    if (tti_csr & CSR_IE)
        SET_INT (TTI);
}

static t_stat console_poll_svc (UNIT *uptr)
{
    int busy = 0;
    if (interrupt_key) {                         /* ^C: ahead of everything waiting */
        interrupt_key = 0;
        fifo_count = 0;
        xoff = 0;
        receive (uptr, CTRL_C | SCPE_KFLAG);
        sim_activate (uptr, clock_share (FAST_PER_S, &fast_acc));
        return SCPE_OK;
    }
    if (!xoff && fifo_count < FIFO_SIZE) {
        int32 c = sim_poll_kbd ();
        if (c >= SCPE_KFLAG) {
            fifo[(fifo_head + fifo_count) % FIFO_SIZE] = c;
            fifo_count++;
            busy = 1;
        } else if (c != SCPE_OK) {               /* ^E and errors: as stock SIMH */
            sim_activate (uptr, slow_interval (uptr));
            return c;
        }
    }
    if (!xoff && fifo_count > 0 && (tti_csr & CSR_DONE) == 0) {
        receive (uptr, fifo[fifo_head]);
        fifo_head = (fifo_head + 1) % FIFO_SIZE;
        fifo_count--;
        busy = 1;
    }
    if (fifo_count > 0 && !xoff)
        busy = 1;
    sim_activate (uptr, busy ? clock_share (FAST_PER_S, &fast_acc) : slow_interval (uptr));
    return SCPE_OK;
}

static t_stat console_print_svc (UNIT *uptr)
{
    int32 c = uptr->buf & 0177;
    if (c == DC3)
        xoff = 1;
    else if (c == DC1 && xoff) {
        xoff = 0;
        sim_cancel (&tti_unit);                  /* go on at once, not at the next tick */
        sim_activate (&tti_unit, 1);
    }
    return tto_svc (uptr);
}

static void on_interrupt_key (int sig)
{
    interrupt_key = 1;
}

void console_pacing_install (void)
{
    struct sigaction action;
    tti_unit.action = &console_poll_svc;
    tto_unit.action = &console_print_svc;
    memset (&action, 0, sizeof action);
    action.sa_handler = on_interrupt_key;
    action.sa_flags = SA_RESTART;
    sigemptyset (&action.sa_mask);
    sigaction (SIGUSR1, &action, NULL);
}

void console_pacing_rate_changed (int32 old_rate)
{
    fast_acc = 0;
}
