/* prompt_cue.c: a stop at the FORTH's prompt that costs nothing while the
   FORTH computes (SIMH device CUE; no bus registers of its own).

   The kernel's QUERY starts with AWAIT-LINE (forth/kernel/quit.fs), which
   reads the DL11's RCSR (177560) once: on a DL11 a read of RCSR changes
   nothing. This file wraps the DL11 receiver's bus read routine (SIMH's own
   tti_rd, pdp11_stddev.c, unpatched): when CUE's register PC is nonzero and
   an RCSR read leaves the CPU's PC equal to it (the instruction after
   AWAIT-LINE's read), a zero-delay event stops the simulator right after that
   instruction, reported as SIMH reports a breakpoint ("Breakpoint, PC: pc").

   A scripted run (harness/machine/scripted_machine.py) deposits AWAIT-LINE's
   address + 4 into CUE PC: it stops at every prompt, puts the next line into
   the console ring and goes on. A SIMH breakpoint on QUERY did the same but
   made SIMH test every instruction's address (1.44-1.61 times slower); here
   the simulator does nothing extra until the FORTH reads RCSR.

   Registers (SIMH, not the bus):
     PC     the stop address (octal); 0 (the power-up value) = never stop
     STOPS  how many times the cue has stopped the simulator */
#include "devices.h"

extern DIB tti_dib;
extern int32 sim_is_running;             /* scp.c: inside sim_instr */
extern int32 R[8];                       /* pdp11_cpu.c: the registers; PC is R[7] */

static int32 cue_pc;
static int32 cue_stops;
static t_stat (*dl11_rd) (int32 *data, int32 PA, int32 access);

static t_stat cue_svc (UNIT *uptr)
{
    cue_stops++;
    return STOP_IBKPT;
}

static UNIT cue_unit = { UDATA (&cue_svc, 0, 0) };

/* RCSR is the receiver's first register. Only the running CPU's reads count:
   an EXAMINE at the sim> prompt reads through here too (io_page_examine.c). */
static t_stat cue_rd (int32 *data, int32 PA, int32 access)
{
    if (cue_pc != 0 && (PA & 2) == 0 && sim_is_running && PC == cue_pc)
        sim_activate (&cue_unit, 0);
    return dl11_rd (data, PA, access);
}

static t_stat cue_reset (DEVICE *dptr)
{
    sim_cancel (&cue_unit);
    return SCPE_OK;
}

static REG cue_reg[] = {
    { ORDATA (PC, cue_pc, 16) },
    { DRDATA (STOPS, cue_stops, 32) },
    { NULL }
};

DEVICE cue_dev = {
    "CUE", &cue_unit, cue_reg, NULL,
    1, 8, 16, 2, 8, 16,
    NULL, NULL, &cue_reset,
    NULL, NULL, NULL,
    NULL, 0
};

void prompt_cue_install (void)
{
    dl11_rd = tti_dib.rd;
    tti_dib.rd = &cue_rd;
}
