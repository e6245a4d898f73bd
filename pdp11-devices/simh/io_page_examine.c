/* io_page_examine.c: EXAMINE and DEPOSIT at an I/O-page address show and set
   what the CPU sees there.

   The machine has 64 KB of memory and no memory management in use, so the
   CPU reads addresses 160000-177777 as the I/O page (17760000-17777777, where
   SHOW CLK and SHOW DRV11 place their registers): EXAMINE 177546 read the
   8 KB of RAM hidden beneath it instead (000000 while the CPU read LKS as
   000300). Here the CPU device's examine and deposit routines are wrapped at
   start-up (machine_sys.c): an address in 160000-177777 is taken as the CPU
   takes it, as SIMH's own -V switch does (virtual, relocated; memory
   management off, that is the I/O page). EXAMINE 17777546 and EXAMINE -V
   177546 work as in stock SIMH; every other address is unchanged. Stock SIMH
   builds its table of I/O registers when the CPU starts, so before the first
   GO every I/O address said "Address space exceeded"; the table is built
   here first (SIMH's own build_dib_tab, as each run does). */
#include "devices.h"

#define IO_WINDOW_LO 0160000
#define IO_WINDOW_HI 0200000

#define IO_PAGE_BASE 017760000

extern DEVICE cpu_dev;
extern t_stat build_dib_tab (void);

static t_stat (*stock_examine) (t_value *vptr, t_addr addr, UNIT *uptr, int32 sw);
static t_stat (*stock_deposit) (t_value val, t_addr addr, UNIT *uptr, int32 sw);

static int32 as_cpu_sees (t_addr addr, int32 sw)
{
    int window = addr >= IO_WINDOW_LO && addr < IO_WINDOW_HI;
    if (window || addr >= IO_PAGE_BASE)
        build_dib_tab ();                        /* the registers as the next run has them */
    return window ? sw | SWMASK ('V') : sw;
}

static t_stat io_examine (t_value *vptr, t_addr addr, UNIT *uptr, int32 sw)
{
    return stock_examine (vptr, addr, uptr, as_cpu_sees (addr, sw));
}

static t_stat io_deposit (t_value val, t_addr addr, UNIT *uptr, int32 sw)
{
    return stock_deposit (val, addr, uptr, as_cpu_sees (addr, sw));
}

void io_page_examine_install (void)
{
    stock_examine = cpu_dev.examine;
    stock_deposit = cpu_dev.deposit;
    cpu_dev.examine = &io_examine;
    cpu_dev.deposit = &io_deposit;
}
