/* machine_sys.c: how the project's devices join SIMH 3.8.1 without patching it.

   Device table. SIMH's scp.c walks sim_devices[] (defined by pdp11_sys.c).
   The build compiles pdp11_sys.c a second time with
   -Dsim_devices=stock_sim_devices, so its table keeps its contents under
   another name, and this file defines the sim_devices[] SIMH uses. It is
   filled at start-up from the stock list: SIMH's CLK (clk_dev, the
   wall-calibrated line clock) is replaced, in its place, by the project's
   KW11-L (kw11l.c, also named CLK); DRV11, AAV11, PLANT, LAB (lab.c,
   the lab bench's pacing, pause and memory watch), CUE (prompt_cue.c, the
   scripted runs' stop at the prompt), LOCKSTEP and LINK0-3 (lockstep_dev.c,
   link_dev.c: the five machines in lock-step, inert until SET LOCKSTEP
   ROLE) are appended.
   Everything else is SIMH's own, in SIMH's order.

   What still refers to the stock clock: pdp11_cpumod.c sets clk_fie,
   clk_fnxm and clk_tps when the CPU model changes, and pdp11_dz.c calls
   clk_cosched(). Those are variables and functions of pdp11_stddev.c that
   only the stock clk_dev's own routines act on; with clk_dev out of the
   table its register, interrupt and service are never installed, so they
   change nothing. tmr_poll and tmxr_poll (console, DZ, RQ timing) are set by
   kw11l.c to the constant RATE/60. sim_idle(TMR_CLK) never idles: the
   calibrated timer it needs is never started; with SET CPU IDLE the KW11-L
   idles the host itself while the CPU WAITs (kw11l.c).

   Hooks. scp.c declares `void (*sim_vm_init)(void)` without initialising it
   and calls it first thing in main(); with -fcommon this file's initialised
   definition is the one linked. machine_vm_init fills the table, replaces the
   console keyboard's service routine (console_pacing.c) and its read routine
   (prompt_cue.c), wraps the CPU's
   examine and deposit for the I/O page (io_page_examine.c), wraps the RL02
   units' service routine so that a written block is fflush()ed and fsync()ed
   before the controller reports it done (rl_durable.c: FLUSH is durable),
   wraps their ATTACH and DETACH so that one simulator writes an image
   (rl_one_writer.c, which also installs sim_vm_read to tell the startup
   script from commands typed at sim>), installs sim_vm_cmd so that QUIT, EXIT
   and BYE FLUSH the FORTH's blocks first (leave_check.c), and
   wraps every DIB's interrupt acknowledge to count the interrupts taken per
   vector (interrupt_count.c), and
   installs sim_vm_post, which scp.c calls after every command (used to end a
   SET PLANT axis selection). */
#include "devices.h"

#define MAX_DEVICES 96

extern DEVICE *stock_sim_devices[];
extern DEVICE clk_dev;
extern void (*sim_vm_post) (t_bool from_scp);

DEVICE *sim_devices[MAX_DEVICES + 1];

static void machine_vm_post (t_bool from_scp)
{
    plant_dev_command_done ();
}

static void add_device (int *n, DEVICE *d)
{
    if (*n >= MAX_DEVICES) {
        fprintf (stderr, "machine_sys: device table full (MAX_DEVICES)\n");
        exit (1);
    }
    sim_devices[(*n)++] = d;
}

static void machine_vm_init (void)
{
    int n = 0;
    for (int i = 0; stock_sim_devices[i] != NULL; i++)
        add_device (&n, stock_sim_devices[i] == &clk_dev ? &kwl_dev : stock_sim_devices[i]);
    add_device (&n, &drv_dev);
    add_device (&n, &aav_dev);
    add_device (&n, &plant_dev);
    add_device (&n, &lab_dev);
    add_device (&n, &cue_dev);
    add_device (&n, &lockstep_dev);
    for (int i = 0; i < 4; i++)
        add_device (&n, &link_dev[i]);
    sim_devices[n] = NULL;
    /* a SET CLK RATE: the plant integrates up to now in the old time; then the
       clock, the plant, the console and the lab keep their events' times */
    clock_on_rate_change (NULL, &kwl_rate_changed);
    clock_on_rate_change (&plant_dev_rate_changing, &plant_dev_rate_changed);
    clock_on_rate_change (NULL, &console_pacing_rate_changed);
    clock_on_rate_change (NULL, &lab_rate_changed);
    clock_on_rate_change (NULL, &lockstep_rate_changed);
    /* the gripper's contact switch is the DRV11's REQ B: the plant, below the
       bus devices, tells the DRV11 through this hook, not by name */
    plant_dev_on_lines_changed (&drv11_lines_changed);
    plant_dev_init ();
    console_pacing_install ();
    prompt_cue_install ();
    io_page_examine_install ();
    rl_durable_install ();
    rl_one_writer_install ();
    leave_check_install ();
    interrupt_count_install ();
    sim_vm_post = &machine_vm_post;
}

void (*sim_vm_init) (void) = &machine_vm_init;
