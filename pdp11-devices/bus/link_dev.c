/* link_dev.c: the DRV11 parallel interfaces that link the 11/23 to its four
   LSI-11/03 axis controllers (SIMH device LINK; the project's continuation,
   docs/controllers.md). Absent (disabled) unless SET LOCKSTEP ROLE names a
   role (simh/lockstep_dev.c); the cable is crossed, DRV11 to DRV11, and what
   one side writes reaches the other at the next lock-step boundary.

   On the 11/23 (ROLE=MAIN) four links, one per axis:
     link     CSR     OUTBUF  INBUF   vectors (A/B, BR4)
     x LINK0  167760  167762  167764  310/314
     y LINK1  167750  167752  167754  320/324
     z LINK2  167740  167742  167744  330/334
     t LINK3  167730  167732  167734  340/344
   On an 11/03 (ROLE=X..T) one link, LINK0 at 167760 (vectors 310/314), to
   the 11/23; LINK1-3 stay disabled.
   The fourth word of each (167766, ...) is not decoded (bus timeout).

   CSR  bit 15 REQ B     read-only: the other side read its INBUF ("data taken")
        bit 8  PEER LOST read-only, the project's addition (not DEC): on the
                         11/23, the 11/03 behind this link has died
        bit 7  REQ A     read-only: the other side wrote its OUTBUF ("new data")
        bit 6  INT ENB A read/write: interrupt at vector A when REQ A sets
        bit 5  INT ENB B read/write: interrupt at vector B when REQ B sets
        bits 1:0         read/write user bits; other bits read 0
   OUTBUF  read/write; a write clears this side's REQ B, and at the next
           boundary the value appears in the other side's INBUF and sets its
           REQ A (the last value written in a quantum crosses)
   INBUF   read-only; a read by the program clears this side's REQ A and at
           the next boundary sets the other side's REQ B (an EXAMINE at sim>
           reads it without either)
   Byte writes change one byte. Power-up and bus INIT clear every register,
   request and enable (PEER LOST stays). The logic is lockstep/link.c. */
#include "devices.h"
#include "lockstep_wire.h"

extern int32 int_req[IPL_HLVL];
extern int32 sim_is_running;

#define INT_V_LINK0 15                   /* BR4 bits after the DRV11's 13, 14: A0 B0 A1 B1 ... */
#define IPL_LINK    4
#define VEC_LINK    0310
#define IOBA_LINK_X (IOPAGEBASE + 007760)   /* 167760; y, z, t below it, 010 apart */

static link_end ends[LS_LINKS];
static int links;                        /* 0 (disabled), 1 (an 11/03) or 4 (the 11/23) */
static int up_a[LS_LINKS], up_b[LS_LINKS];

static t_stat link_rd (int32 *data, int32 PA, int32 access);
static t_stat link_wr (int32 data, int32 PA, int32 access);
static t_stat link_reset (DEVICE *dptr);
static t_stat link_show_state (FILE *st, UNIT *uptr, int32 val, void *desc);

#define LINK_DIB(i) { IOBA_LINK_X - 010 * (i), 010, &link_rd, &link_wr, \
                      2, IPL_LINK * 32 + INT_V_LINK0 + 2 * (i), VEC_LINK + 010 * (i), { NULL } }
static DIB link_dib[LS_LINKS] = { LINK_DIB (0), LINK_DIB (1), LINK_DIB (2), LINK_DIB (3) };

static UNIT link_unit[LS_LINKS] = {
    { UDATA (NULL, 0, 0) }, { UDATA (NULL, 0, 0) }, { UDATA (NULL, 0, 0) }, { UDATA (NULL, 0, 0) }
};

static MTAB link_mod[] = {
    { MTAB_XTD|MTAB_VDV, 0, "STATE", NULL, NULL, &link_show_state, NULL },
    { MTAB_XTD|MTAB_VDV, 0, "ADDRESS", NULL, NULL, &show_addr, NULL },
    { MTAB_XTD|MTAB_VDV, 0, "VECTOR", NULL, NULL, &show_vec, NULL },
    { 0 }
};

#define LINK_DEVICE(i, name) { name, &link_unit[i], NULL, link_mod, \
    1, 8, 16, 2, 8, 16, NULL, NULL, &link_reset, NULL, NULL, NULL, \
    &link_dib[i], DEV_UBUS | DEV_QBUS | DEV_DIS }
DEVICE link_dev[LS_LINKS] = {
    LINK_DEVICE (0, "LINK0"), LINK_DEVICE (1, "LINK1"),
    LINK_DEVICE (2, "LINK2"), LINK_DEVICE (3, "LINK3")
};

/* A request is up while INT ENB x and REQ x are; raised only on the rising edge. */
static void update_ints (int i)
{
    int a = link_int_a (&ends[i]), b = link_int_b (&ends[i]);
    int32 bit_a = 1u << (INT_V_LINK0 + 2 * i), bit_b = bit_a << 1;
    if (a && !up_a[i]) int_req[IPL_LINK] |= bit_a;
    if (!a) int_req[IPL_LINK] &= ~bit_a;
    if (b && !up_b[i]) int_req[IPL_LINK] |= bit_b;
    if (!b) int_req[IPL_LINK] &= ~bit_b;
    up_a[i] = a;
    up_b[i] = b;
}

void link_dev_configure (int n)
{
    links = n;
    for (int i = 0; i < LS_LINKS; i++) {
        if (i < n) link_dev[i].flags &= ~DEV_DIS;
        else link_dev[i].flags |= DEV_DIS;
        ends[i].lost = 0;
    }
    link_reset (NULL);
}

link_wire link_dev_take_wire (int i)
{
    link_wire none = { 0 };
    return i < links ? link_take_wire (&ends[i]) : none;
}

void link_dev_deliver (int i, link_wire w)
{
    if (i >= links) return;
    link_deliver (&ends[i], w);
    update_ints (i);
}

void link_dev_peer_lost (int i)
{
    if (i < links) link_set_lost (&ends[i]);
}

static int end_of (int32 PA)             /* x at the top, then y, z, t downwards */
{
    return (IOBA_LINK_X - (PA & ~07)) >> 3;
}

static t_stat link_rd (int32 *data, int32 PA, int32 access)
{
    int i = end_of (PA);
    link_end *e = &ends[i];
    switch ((PA >> 1) & 03) {
    case 0: *data = link_read_csr (e); break;
    case 1: *data = e->outbuf; break;
    case 2:
        *data = sim_is_running ? link_read_inbuf (e) : e->inbuf;
        update_ints (i);
        break;
    default: return SCPE_NXM;
    }
    return SCPE_OK;
}

static t_stat link_wr (int32 data, int32 PA, int32 access)
{
    int i = end_of (PA);
    link_end *e = &ends[i];
    switch ((PA >> 1) & 03) {
    case 0: link_write_csr (e, (uint16) MERGE_BYTE (e->csr, data, PA, access)); break;
    case 1: link_write_outbuf (e, (uint16) MERGE_BYTE (e->outbuf, data, PA, access)); break;
    case 2: break;                               /* INBUF is read-only */
    default: return SCPE_NXM;
    }
    update_ints (i);
    return SCPE_OK;
}

static t_stat link_reset (DEVICE *dptr)         /* every link: they share one bus INIT */
{
    for (int i = 0; i < LS_LINKS; i++) {
        link_init (&ends[i]);
        up_a[i] = up_b[i] = 1;                   /* so that update_ints clears both */
        update_ints (i);
    }
    return SCPE_OK;
}

static t_stat link_show_state (FILE *st, UNIT *uptr, int32 val, void *desc)
{
    int i = (int) (uptr - link_unit);
    if (i >= links) {
        fprintf (st, "not in use (SET LOCKSTEP ROLE=...)");
        return SCPE_OK;
    }
    fprintf (st, "CSR=%06o OUTBUF=%06o INBUF=%06o", link_read_csr (&ends[i]),
             ends[i].outbuf, ends[i].inbuf);
    return SCPE_OK;
}
