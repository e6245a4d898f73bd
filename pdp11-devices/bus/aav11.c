/* aav11.c: AAV11-A four-channel D/A converter (SIMH device AAV11), the axes'
   velocity commands (docs/design.md section 2). No interrupts.

   170440 DAC x, 170442 DAC y, 170444 DAC z, 170446 DAC t
     bits 11:0  code, offset binary: 0 = -10.000 V, 2048 = 0 V, 4095 = +9.995 V
     bits 15:12 ignored on write, read as 0
   A read returns the code last written. A byte write changes one byte (the
   high byte's bits 15:12 are dropped as above). Power-up and bus INIT set every
   channel to 2048. Every write (and INIT) goes to the plant at once. */
#include "devices.h"

#define IOBA_AAV  (IOPAGEBASE + 010440)         /* 170440 */
#define CODE_MASK 07777

static uint16 dac[PLANT_AXES];         /* uint16: the REG table (12-bit BRDATA) steps by 2 bytes */

static t_stat aav_rd (int32 *data, int32 PA, int32 access);
static t_stat aav_wr (int32 data, int32 PA, int32 access);
static t_stat aav_reset (DEVICE *dptr);
static t_stat aav_show_state (FILE *st, UNIT *uptr, int32 val, void *desc);

static DIB aav_dib = { IOBA_AAV, 2 * PLANT_AXES, &aav_rd, &aav_wr, 0, 0, 0, { NULL } };

static UNIT aav_unit = { UDATA (NULL, 0, 0) };

static REG aav_reg[] = {
    { BRDATA (DAC, dac, 8, 12, PLANT_AXES), REG_RO },
    { NULL }
};

static MTAB aav_mod[] = {
    { MTAB_XTD|MTAB_VDV, 0, "STATE", NULL, NULL, &aav_show_state, NULL },
    { MTAB_XTD|MTAB_VDV, 0, "ADDRESS", NULL, NULL, &show_addr, NULL },
    { 0 }
};

DEVICE aav_dev = {
    "AAV11", &aav_unit, aav_reg, aav_mod,
    1, 8, 16, 2, 8, 16,
    NULL, NULL, &aav_reset,
    NULL, NULL, NULL,
    &aav_dib, DEV_UBUS | DEV_QBUS
};

static t_stat aav_rd (int32 *data, int32 PA, int32 access)
{
    *data = dac[(PA >> 1) & 03];
    return SCPE_OK;
}

static t_stat aav_wr (int32 data, int32 PA, int32 access)
{
    int ch = (PA >> 1) & 03;
    dac[ch] = MERGE_BYTE (dac[ch], data, PA, access) & CODE_MASK;
    plant_dev_dac (ch, dac[ch]);
    return SCPE_OK;
}

static t_stat aav_reset (DEVICE *dptr)
{
    for (int ch = 0; ch < PLANT_AXES; ch++) {
        dac[ch] = PLANT_CODE_ZERO;
        plant_dev_dac (ch, dac[ch]);
    }
    return SCPE_OK;
}

static t_stat aav_show_state (FILE *st, UNIT *uptr, int32 val, void *desc)
{
    for (int ch = 0; ch < PLANT_AXES; ch++)
        fprintf (st, "%s%c=%04d (%+.3f V)", ch ? " " : "", plant_axis_names[ch], dac[ch],
                 (dac[ch] - PLANT_CODE_ZERO) * (10.0 / 2048.0));
    return SCPE_OK;
}
