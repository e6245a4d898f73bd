/* drv11.c: DRV11 parallel interface (SIMH device DRV11), wired as the robot's
   encoder-counter multiplexer (docs/design.md section 2).

   167770 CSR   bits 1:0  CSR1, CSR0  read/write: multiplexer select
                                      0 = x, 1 = y, 2 = z, 3 = t
                bit 6     INT ENB A   read/write
                bit 5     INT ENB B   read/write
                bit 7     REQ A       read-only (user device's request A line)
                bit 15    REQ B       read-only (user device's request B line)
                other bits read 0; writes to them are ignored
   167772 OUTBUF  16-bit read/write latch; bits 3:0 are the four counters' run
                lines (bit n, axis n): 0 clears the counter and holds it at 0,
                1 lets it count
                bit 4  gripper STEP: a 0-to-1 edge asks the stepper for one step
                bit 5  gripper DIR: 1 = close the fingers, 0 = open them
                (the project's continuation, gripper.h; bits 15:6 drive nothing)
   167774 INBUF   read-only: the selected axis counter, 16-bit two's
                complement, wrapping modulo 65536; writes are ignored
   Byte writes change one byte of a register (CSR: only its writable bits).
   Power-up and bus INIT: CSR and OUTBUF 0 (counters held at zero).

   Interrupts: vector 300 (A) and 304 (B), BR4. A request is raised when INT
   ENB x and REQ x become both 1 and withdrawn when either drops. The counter
   multiplexer drives neither REQ line. REQ B is 1 while the gripper's finger
   contact switch is closed (fingers on an object), or-ed with what the
   console set. `SET DRV11 REQA=1` (REQB) drives the line from the console,
   standing for a user device, which is how the interrupt logic is tested. */
#include "devices.h"

extern int32 int_req[IPL_HLVL];

#define INT_V_DRVA 13                   /* BR4 bits SIMH leaves free */
#define INT_V_DRVB 14
#define IPL_DRVA   4
#define IPL_DRVB   4
#define INT_DRVA   (1u << INT_V_DRVA)
#define INT_DRVB   (1u << INT_V_DRVB)
#define VEC_DRV    0300
#define IOBA_DRV11_ADDR (IOPAGEBASE + 007770)   /* 167770 */

#define CSR_SEL    0000003
#define CSR_IEB    0000040
#define CSR_IEA    0000100
#define CSR_REQA   0000200
#define CSR_REQB   0100000
#define CSR_RW     (CSR_SEL | CSR_IEB | CSR_IEA)

static int32 drv_csr;                    /* writable bits */
static int32 drv_req;                    /* REQ A / REQ B set from the console, in CSR positions */
static int drv_up_a, drv_up_b;           /* request conditions at the last update */
static int32 drv_outbuf;

static t_stat drv_rd (int32 *data, int32 PA, int32 access);
static t_stat drv_wr (int32 data, int32 PA, int32 access);
static t_stat drv_reset (DEVICE *dptr);
static t_stat drv_set_req (UNIT *uptr, int32 val, char *cptr, void *desc);
static t_stat drv_show_state (FILE *st, UNIT *uptr, int32 val, void *desc);

static DIB drv_dib = {
    IOBA_DRV11_ADDR, 6, &drv_rd, &drv_wr,
    2, IVCL (DRVA), VEC_DRV, { NULL, NULL }
};

static UNIT drv_unit = { UDATA (NULL, 0, 0) };

static REG drv_reg[] = {
    { ORDATA (CSR, drv_csr, 16), REG_RO },
    { ORDATA (OUTBUF, drv_outbuf, 16), REG_RO },
    { FLDATA (REQA, drv_req, 7), REG_RO },
    { FLDATA (REQB, drv_req, 15), REG_RO },
    { FLDATA (INTA, IREQ (DRVA), INT_V_DRVA) },
    { FLDATA (INTB, IREQ (DRVB), INT_V_DRVB) },
    { NULL }
};

static MTAB drv_mod[] = {
    { MTAB_XTD|MTAB_VDV, CSR_REQA, NULL, "REQA", &drv_set_req, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, CSR_REQB, NULL, "REQB", &drv_set_req, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, 0, "STATE", NULL, NULL, &drv_show_state, NULL },
    { MTAB_XTD|MTAB_VDV, 0, "ADDRESS", NULL, NULL, &show_addr, NULL },
    { MTAB_XTD|MTAB_VDV, 0, "VECTOR", NULL, NULL, &show_vec, NULL },
    { 0 }
};

DEVICE drv_dev = {
    "DRV11", &drv_unit, drv_reg, drv_mod,
    1, 8, 16, 2, 8, 16,
    NULL, NULL, &drv_reset,
    NULL, NULL, NULL,
    &drv_dib, DEV_UBUS | DEV_QBUS
};

static int32 drv_lines (void)            /* REQ A and REQ B as the CSR shows them */
{
    return drv_req | (plant_dev_gripper_contact () ? CSR_REQB : 0);
}

/* Request x is up while INT ENB x and REQ x are; raise only on the rising edge. */
static void drv_update_ints (void)
{
    int32 lines = drv_lines ();
    int is_a = (drv_csr & CSR_IEA) && (lines & CSR_REQA);
    int is_b = (drv_csr & CSR_IEB) && (lines & CSR_REQB);
    if (is_a && !drv_up_a) SET_INT (DRVA);
    if (!is_a) CLR_INT (DRVA);
    if (is_b && !drv_up_b) SET_INT (DRVB);
    if (!is_b) CLR_INT (DRVB);
    drv_up_a = is_a;
    drv_up_b = is_b;
}

void drv11_lines_changed (void)
{
    drv_update_ints ();
}

static t_stat drv_rd (int32 *data, int32 PA, int32 access)
{
    switch ((PA >> 1) & 03) {
    case 0: *data = drv_csr | drv_lines (); break;
    case 1: *data = drv_outbuf; break;
    case 2: *data = plant_dev_counter (drv_csr & CSR_SEL); break;
    default: return SCPE_NXM;
    }
    return SCPE_OK;
}

static t_stat drv_wr (int32 data, int32 PA, int32 access)
{
    switch ((PA >> 1) & 03) {
    case 0:
        drv_csr = MERGE_BYTE (drv_csr, data, PA, access) & CSR_RW;
        drv_update_ints ();
        break;
    case 1:
        drv_outbuf = MERGE_BYTE (drv_outbuf, data, PA, access) & 0177777;
        plant_dev_run_lines (drv_outbuf & 017);
        plant_dev_gripper_lines ((drv_outbuf >> 4) & 1, (drv_outbuf >> 5) & 1);
        drv_update_ints ();                      /* a step may close the contact */
        break;
    case 2:                                      /* INBUF is read-only */
        break;
    default:
        return SCPE_NXM;
    }
    return SCPE_OK;
}

static t_stat drv_reset (DEVICE *dptr)
{
    drv_csr = 0;
    drv_outbuf = 0;
    drv_up_a = drv_up_b = 0;
    CLR_INT (DRVA);
    CLR_INT (DRVB);
    plant_dev_run_lines (0);
    plant_dev_gripper_lines (0, 0);
    return SCPE_OK;
}

static t_stat drv_set_req (UNIT *uptr, int32 bit, char *cptr, void *desc)
{
    if (cptr == NULL || (strcmp (cptr, "0") != 0 && strcmp (cptr, "1") != 0)) {
        printf ("REQA and REQB take 0 or 1\n");
        return SCPE_ARG;
    }
    drv_req = (*cptr == '1') ? (drv_req | bit) : (drv_req & ~bit);
    drv_update_ints ();
    return SCPE_OK;
}

static t_stat drv_show_state (FILE *st, UNIT *uptr, int32 val, void *desc)
{
    fprintf (st, "CSR=%06o (select %c, IEA=%d IEB=%d REQA=%d REQB=%d), OUTBUF=%06o",
             drv_csr | drv_lines (), plant_axis_names[drv_csr & CSR_SEL],
             (drv_csr & CSR_IEA) != 0, (drv_csr & CSR_IEB) != 0,
             (drv_lines () & CSR_REQA) != 0, (drv_lines () & CSR_REQB) != 0, drv_outbuf);
    return SCPE_OK;
}
