/* io_break.c: a breakpoint on an I/O register access (SET LAB IOBREAK=addr).

   SIMH 3.8.1's PDP-11 breakpoints stop on execution only. This one stops the
   machine after the CPU reads or writes one I/O page register, with a line
   naming the register, the access, the value and the instruction's PC:
     I/O break: write 004000 to 170440 (AAV11-A DAC X) at PC 024614
   then SIMH's own "Simulation stopped" and sim>; CONT goes on from the next
   instruction, so nothing in simulated time changes.

   How, without patching SIMH: every run rebuilds the I/O page's dispatch from
   the devices' DIBs (build_dib_tab), so the read and write routines of the DIB
   that answers at the address are wrapped while the break is set (and put
   back when it is cleared or moved). The wrapper calls the device's own
   routine, then, for the watched address and only while the CPU runs (an
   EXAMINE at sim> reads through the same routine), prints the line and sets
   the CPU's cpu_astop, which stops it before the next instruction. The PC is
   the accessing instruction's: MMR2's, which the CPU sets to each
   instruction's address as it fetches it.

   SET LAB IOBREAK=addr   addr octal, even: 160000-177776 (or 17760000-17777776)
                          where a device of the table answers; another refused
                          with a line saying why, and the break set before stays
   SET LAB NOIOBREAK      clear it
   SHOW LAB IOBREAK       where it is */
#include "devices.h"

#define IO_LO 0160000
#define IO_HI 0200000
#define IO_PAGE_BASE 017760000

extern DEVICE *sim_devices[];
extern int32 cpu_astop, MMR2;
extern int32 sim_is_running;

static const struct { int32 address; const char *name; } known[] = {   /* the robot's */
    { 0177546, "KW11-L LKS" },
    { 0167770, "DRV11 CSR" }, { 0167772, "DRV11 OUTBUF" }, { 0167774, "DRV11 INBUF" },
    { 0170440, "AAV11-A DAC X" }, { 0170442, "AAV11-A DAC Y" },
    { 0170444, "AAV11-A DAC Z" }, { 0170446, "AAV11-A DAC T" },
    { 0177560, "DL11 RCSR" }, { 0177562, "DL11 RBUF" },
    { 0177564, "DL11 XCSR" }, { 0177566, "DL11 XBUF" },
    { 0174400, "RL11 CS" }, { 0174402, "RL11 BA" }, { 0174404, "RL11 DA" }, { 0174406, "RL11 MP" },
};

static int32 watched = -1;              /* the address, 160000-177776; -1 none */
static DEVICE *dev;
static DIB *dib;
static t_stat (*stock_rd) (int32 *data, int32 pa, int32 access);
static t_stat (*stock_wr) (int32 data, int32 pa, int32 access);

static int32 io_address (int32 pa)       /* 160000-177777, as the program names it */
{
    return (pa & IOPAGEMASK) | IO_LO;
}

static void register_name (char *buf, int32 address)
{
    for (size_t i = 0; i < sizeof known / sizeof known[0]; i++)
        if (known[i].address == address) {
            strcpy (buf, known[i].name);
            return;
        }
    sprintf (buf, "%s +%o", sim_dname (dev), (int) (address - io_address (dib->ba)));
}

static void hit (int32 pa, const char *what, const char *to, int32 value)
{
    char name[64];
    if (!sim_is_running || (io_address (pa) & ~1) != watched)
        return;
    register_name (name, watched);
    printf ("\r\nI/O break: %s %06o %s %06o (%s) at PC %06o\r\n",
            what, (int) (value & 0177777), to, (int) io_address (pa), name, (int) (MMR2 & 0177777));
    fflush (stdout);
    cpu_astop = 1;                       /* stop before the next instruction */
}

static t_stat break_rd (int32 *data, int32 pa, int32 access)
{
    t_stat r = stock_rd (data, pa, access);
    if (r == SCPE_OK)
        hit (pa, "read", "from", *data);
    return r;
}

static t_stat break_wr (int32 data, int32 pa, int32 access)
{
    t_stat r = stock_wr (data, pa, access);
    if (r == SCPE_OK)
        hit (pa, access == WRITEB ? "byte write" : "write", "to", data);
    return r;
}

static void unwrap (void)
{
    if (dib) {
        dib->rd = stock_rd;
        dib->wr = stock_wr;
    }
    dib = NULL;
    dev = NULL;
    watched = -1;
}

/* The enabled device whose DIB answers at `address` (160000-177776), or NULL. */
static DEVICE *answering (int32 address, DIB **found)
{
    for (int i = 0; sim_devices[i] != NULL; i++) {
        DIB *d = (DIB *) sim_devices[i]->ctxt;
        int32 lo;
        if (d == NULL || (sim_devices[i]->flags & DEV_DIS) || d->lnt == 0)
            continue;
        lo = io_address (d->ba);
        if ((d->ba & ~IOPAGEMASK) == IOPAGEBASE && address >= lo
            && (uint32) (address - lo) < d->lnt) {
            *found = d;
            return sim_devices[i];
        }
    }
    return NULL;
}

t_stat io_break_set (char *cptr)
{
    char *end;
    long a = cptr ? strtol (cptr, &end, 8) : -1;
    DIB *d = NULL;
    DEVICE *found;
    if (cptr == NULL || end == cptr || *end != 0) {
        printf ("IOBREAK: give an octal I/O page address, as SET LAB IOBREAK=170440\n");
        return SCPE_ARG;
    }
    if (a >= IO_PAGE_BASE && a < IO_PAGE_BASE + (IO_HI - IO_LO))
        a = a - IO_PAGE_BASE + IO_LO;
    if (a < IO_LO || a >= IO_HI || (a & 1)) {
        printf ("IOBREAK: %lo is not an even I/O page address (160000-177776)\n", a);
        return SCPE_ARG;
    }
    if ((found = answering ((int32) a, &d)) == NULL) {
        printf ("IOBREAK: no device answers at %06lo (SHOW DEVICES lists them; the CPU's "
                "own registers cannot be watched)\n", a);
        return SCPE_ARG;
    }
    if (d->rd == NULL || d->wr == NULL) {
        printf ("IOBREAK: %s's registers cannot be watched\n", sim_dname (found));
        return SCPE_ARG;
    }
    unwrap ();
    dev = found;
    dib = d;
    stock_rd = d->rd;
    stock_wr = d->wr;
    d->rd = &break_rd;
    d->wr = &break_wr;
    watched = (int32) a;
    return SCPE_OK;
}

t_stat io_break_clear (void)
{
    unwrap ();
    return SCPE_OK;
}

void io_break_show (FILE *st)
{
    char name[64];
    if (watched < 0) {
        fprintf (st, "no I/O break");
        return;
    }
    register_name (name, watched);
    fprintf (st, "I/O break at %06o (%s), read or write", watched, name);
}
