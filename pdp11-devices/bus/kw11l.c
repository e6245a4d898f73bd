/* kw11l.c: KW11-L line clock (SIMH device CLK); SET CLK RATE sets the time base.

   Register (docs/design.md section 2), 177546 LKS, vector 100, BR6:
     bit 7  MONITOR  set by every tick; cleared by writing a 0 to it (a 1
                     written leaves it as it is); 0 at power-up and bus INIT
     bit 6  INT ENB  read/write; 0 at power-up and bus INIT
     other bits read 0; a write to the high byte changes nothing.
   A tick with INT ENB set requests an interrupt at vector 100 (BR6); clearing
   INT ENB withdraws a request not yet taken. Setting INT ENB between ticks
   does not interrupt: only ticks do.

   Unlike SIMH's stock clock (pdp11_stddev.c, calibrated against the host's
   wall clock, register missing and interrupts forced on for an 11/23), this
   one ticks exactly 60 times per simulated second: tick n comes after
   floor(n * RATE / 60) executed instructions, whatever the host does. Bus
   INIT does not restart the series (the mains keep running).

   Time base (time_base.c): simulated seconds = instructions / RATE (SET CLK
   RATE=n, default 300000, the KDF11-A's typical speed). Changing RATE keeps
   the time continuous: pending ticks and trace samples keep their simulated
   times (every device registers for it; kwl_rate_changed is the clock's part).

   Devices SIMH paces from the clock (console polling, RQ's timer) read
   tmr_poll/tmxr_poll: they are set to RATE/60 instructions, a constant.

   SET CLK TIMED (NOTIMED to end; kdf11_time.c): each instruction advances
   time by its KDF11-A execution time instead of one count, RATE becomes
   13333333 units of 75 ns a second: the ticks come every real 1/60 s of an
   11/23's time.

   Pacing to the wall clock (wall_pacer.c, shared with the LAB device; pacing
   changes only when things happen on the host: every event keeps its
   instruction count, so runs stay deterministic). At a tick, the clock sleeps
   the host while simulated time is ahead of the wall clock since a reference
   point; a reference more than 100 ms behind (the machine was stopped at
   sim>, or the host was slow) is dropped and taken anew, so no burst follows.
     SET CLK REALTIME (NOREALTIME to end): every tick, busy or not: the 11/23's
       real pace from the first instruction. The console's real-time mode uses
       it: SIMH 3.8.1's SET THROTTLE cannot pace WAIT (measured: a WAIT loop ran
       16 times too fast) and measures the host anew after every CONT.
     SET CPU IDLE (SIMH's own switch; the console's --fast sets it): only ticks
       that find the CPU in WAIT (the kernel's KEY waiting for a key), so an
       idle prompt passes at the real pace and costs the host little while
       busy stretches run at full speed. (SIMH's own sim_idle needs a
       wall-calibrated timer, which this clock never is.)
     SET CLK IDLESPEED=X (1..1000, default 1): those idle ticks pass at X times
       the real pace. The harness's pty machine (harness/machine/machine.py)
       uses 100: an idle prompt there would otherwise race simulated time (about
       700 times the real pace) and keep a host core busy between two lines.
   Without either (scripted runs) WAIT costs one count per simulated
   instruction time, as in stock SIMH. */
#include "devices.h"

extern int32 int_req[IPL_HLVL];
extern int32 tmr_poll, tmxr_poll;
extern int32 wait_state;                /* pdp11_cpu.c: the CPU is in WAIT */
extern t_bool sim_idle_enab;            /* sim_timer.c: SET CPU IDLE */

#define LKS_MON  0200
#define LKS_IE   0100
#define RATE_MIN 1000
#define RATE_MAX 100000000
#define TICKS_PER_S 60

static int32 lks;
static clock_series ticks_due;          /* the exact tick series (time_base.c) */
static uint32 ticks;                    /* ticks since power-up */
static int realtime;                    /* SET CLK REALTIME */
static int32 idle_speed = 1;            /* SET CLK IDLESPEED: idle ticks' pace */
#define IDLE_SPEED_MAX 1000
static wall_pacer pacer;                 /* wall_pacer.c */
#define PACE_SLACK_S 0.1                /* further behind: take a new reference */

static t_stat kwl_rd (int32 *data, int32 PA, int32 access);
static t_stat kwl_wr (int32 data, int32 PA, int32 access);
static t_stat kwl_svc (UNIT *uptr);
static t_stat kwl_reset (DEVICE *dptr);
static t_stat kwl_set_rate (UNIT *uptr, int32 val, char *cptr, void *desc);
static t_stat kwl_show_rate (FILE *st, UNIT *uptr, int32 val, void *desc);
static t_stat kwl_show_state (FILE *st, UNIT *uptr, int32 val, void *desc);
static t_stat kwl_set_realtime (UNIT *uptr, int32 val, char *cptr, void *desc);
static t_stat kwl_set_idle_speed (UNIT *uptr, int32 val, char *cptr, void *desc);
static t_stat kwl_show_idle_speed (FILE *st, UNIT *uptr, int32 val, void *desc);
/* A SET value that must be a whole number in lo..hi: SCPE_OK and *x, or the
   refusal (`why` printed, nothing changed). */
static t_stat whole_number (const char *cptr, long lo, long hi, const char *why, long *x)
{
    char *end;
    if (cptr == NULL || *cptr == 0)
        return SCPE_MISVAL;
    *x = strtol (cptr, &end, 10);
    if (*end != 0 || *x < lo || *x > hi) {
        printf ("%s, %ld..%ld\n", why, lo, hi);
        return SCPE_ARG;
    }
    return SCPE_OK;
}

static t_stat kwl_set_idle_speed (UNIT *uptr, int32 val, char *cptr, void *desc)
{
    long x;
    t_stat r = whole_number (cptr, 1, IDLE_SPEED_MAX,
                             "IDLESPEED must be a whole number of times the real pace", &x);
    if (r != SCPE_OK)
        return r;
    idle_speed = (int32) x;
    wall_pacer_drop (&pacer);
    return SCPE_OK;
}

static t_stat kwl_show_idle_speed (FILE *st, UNIT *uptr, int32 val, void *desc)
{
    fprintf (st, "idlespeed=%d\n", idle_speed);      /* MTAB_NMO: SIMH ends no line */
    return SCPE_OK;
}

static t_stat kwl_set_timed (UNIT *uptr, int32 val, char *cptr, void *desc);

static DIB kwl_dib = {
    IOBA_CLK, IOLN_CLK, &kwl_rd, &kwl_wr,
    1, IVCL (CLK), VEC_CLK, { NULL }
};

static UNIT kwl_unit = { UDATA (&kwl_svc, 0, 0) };

static REG kwl_reg[] = {
    { ORDATA (LKS, lks, 16) },
    { FLDATA (INT, IREQ (CLK), INT_V_CLK) },
    { FLDATA (MON, lks, 7) },
    { FLDATA (IE, lks, 6) },
    { DRDATA (RATE, clock_rate, 32), PV_LEFT + REG_RO },
    { DRDATA (TICKS, ticks, 32), PV_LEFT + REG_RO },
    { NULL }
};

static MTAB kwl_mod[] = {
    { MTAB_XTD|MTAB_VDV, 0, "RATE", "RATE", &kwl_set_rate, &kwl_show_rate, NULL },
    { MTAB_XTD|MTAB_VDV, 0, "STATE", NULL, NULL, &kwl_show_state, NULL },
    { MTAB_XTD|MTAB_VDV, 1, NULL, "REALTIME", &kwl_set_realtime, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, 0, NULL, "NOREALTIME", &kwl_set_realtime, NULL, NULL },
    { MTAB_XTD|MTAB_VDV|MTAB_NMO, 0, "IDLESPEED", "IDLESPEED", &kwl_set_idle_speed,
      &kwl_show_idle_speed, NULL },
    { MTAB_XTD|MTAB_VDV, 1, NULL, "TIMED", &kwl_set_timed, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, 0, NULL, "NOTIMED", &kwl_set_timed, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, 0, "ADDRESS", NULL, NULL, &show_addr, NULL },
    { MTAB_XTD|MTAB_VDV, 0, "VECTOR", NULL, NULL, &show_vec, NULL },
    { 0 }
};

DEVICE kwl_dev = {
    "CLK", &kwl_unit, kwl_reg, kwl_mod,
    1, 0, 0, 0, 0, 0,
    NULL, NULL, &kwl_reset,
    NULL, NULL, NULL,
    &kwl_dib, DEV_UBUS | DEV_QBUS
};

static t_stat kwl_rd (int32 *data, int32 PA, int32 access)
{
    *data = lks & (LKS_MON | LKS_IE);
    return SCPE_OK;
}

static t_stat kwl_wr (int32 data, int32 PA, int32 access)
{
    if ((access == WRITEB) && (PA & 1))          /* high byte: no bits there */
        return SCPE_OK;
    if ((data & LKS_MON) == 0)
        lks &= ~LKS_MON;
    lks = (lks & ~LKS_IE) | (data & LKS_IE);
    if ((lks & LKS_IE) == 0)
        CLR_INT (CLK);
    return SCPE_OK;
}

/* At a tick: sleep while simulated time is ahead of the host's (see above). */
static void pace (void)
{
    if (realtime)
        wall_pacer_pace (&pacer, 1.0, PACE_SLACK_S);
    else if (sim_idle_enab && wait_state)
        wall_pacer_pace (&pacer, (double) idle_speed, PACE_SLACK_S);
    else
        wall_pacer_drop (&pacer);
}

static t_stat kwl_svc (UNIT *uptr)
{
    pace ();
    ticks++;
    lks |= LKS_MON;
    if (lks & LKS_IE)
        SET_INT (CLK);
    clock_series_next (uptr, &ticks_due, TICKS_PER_S);
    return SCPE_OK;
}

static t_stat kwl_reset (DEVICE *dptr)
{
    lks = 0;
    CLR_INT (CLK);
    tmr_poll = tmxr_poll = clock_rate / TICKS_PER_S;
    if (!sim_is_active (&kwl_unit)) {            /* power-up: start the series */
        clock_series_start (&ticks_due);
        clock_series_next (&kwl_unit, &ticks_due, TICKS_PER_S);
    }
    return SCPE_OK;
}

static t_stat kwl_set_rate (UNIT *uptr, int32 val, char *cptr, void *desc)
{
    long x;
    t_stat r = whole_number (cptr, RATE_MIN, RATE_MAX,
                             "RATE must be a whole number of instructions per second", &x);
    if (r != SCPE_OK)
        return r;
    clock_set_rate ((int32) x);                 /* time_base.c: every device is told */
    return SCPE_OK;
}

void kwl_rate_changed (int32 old_rate)
{
    tmr_poll = tmxr_poll = clock_rate / TICKS_PER_S;
    clock_series_rescale (&kwl_unit, &ticks_due, old_rate);   /* the next tick keeps its time */
}

static t_stat kwl_set_realtime (UNIT *uptr, int32 val, char *cptr, void *desc)
{
    if (cptr != NULL)
        return SCPE_ARG;
    realtime = val;
    wall_pacer_drop (&pacer);
    return SCPE_OK;
}

static t_stat kwl_set_timed (UNIT *uptr, int32 val, char *cptr, void *desc)
{
    if (cptr != NULL)
        return SCPE_ARG;
    return kdf11_time_set (val);                /* kdf11_time.c */
}

static t_stat kwl_show_rate (FILE *st, UNIT *uptr, int32 val, void *desc)
{
    fprintf (st, "rate=%d %s/s%s", clock_rate,
             kdf11_timed ? "units (timed: KDF11-A times in 75 ns units)" : "instructions",
             realtime ? ", realtime" : "");
    return SCPE_OK;
}

static t_stat kwl_show_state (FILE *st, UNIT *uptr, int32 val, void *desc)
{
    fprintf (st, "LKS=%06o (IE=%d MON=%d), %.0f ticks, time=%.6fs", lks,
             (lks & LKS_IE) != 0, (lks & LKS_MON) != 0, (double) ticks, clock_time ());
    return SCPE_OK;
}
