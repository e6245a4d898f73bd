/* plant_dev.c: SIMH glue for the four-axis plant and the gripper (SIMH
   device PLANT). The physics is plant.c and gripper.c; this file only
   connects them to simulated time, the bus devices (aav11.c, drv11.c: the
   gripper's STEP and DIR lines are DRV11 OUTBUF bits 4 and 5, its contact
   switch is REQ B), SET/SHOW and the trace file. No bus registers.

   SET (one axis selected by its letter, then any of its parameters):
     SET PLANT X TAU=20             SET PLANT Z KV=19.53,OFFSET=45
     parameters: KV (counts/s per code), TAU (ms), AMAX (counts/s^2),
     VMAX (counts/s), OFFSET (codes; restarts that axis's walk), PMIN, PMAX
     (end stops, counts), WALK (offset random walk, codes per sqrt(s)),
     POS (counts: puts the axis there at rest; a running counter counts it)
     device-wide: SET PLANT SEED=n (random walk seed, default 1983),
     SET PLANT SAMPLE=n (trace samples per simulated second, 0..1000,
     default 60; 0 = rows at DAC writes only), SET PLANT POWER=ON|OFF (the
     amplifier rack's power switch, plant.h; on at power-up of the simulator;
     the interactive console switches it off at boot), SET PLANT HINT=ON|OFF
     (a line at the console when a move waits on the rack switched off:
     rack_hint.c; off at power-up, the interactive console switches it on);
     the gripper (the project's continuation, docs/continuation.md):
     SET PLANT GRIPPER OBJECT=1.0   (an object that wide between the fingers,
     inches; 0 = none; refused while the fingers are closer than that),
     PULLOUT=300 (steps/s the motor follows), OPENING=2 (inches, 0..2);
     PARTX=, PARTY=, PARTZ= (counts, as the counters read) make the object a
     part at that place, between the fingers only when the hand is there
     and carried while gripped (gripper.h); OBJECT=0 removes it
   A rejected value (non-number, out of range, no axis selected) prints why,
   returns a SIMH error and leaves that parameter as it was; modifiers are
   applied left to right. The selection lasts until the end of the command.
   SHOW PLANT: per axis position (counts and inches or degrees), velocity,
   DAC code, commanded velocity, offset, end stop, run line, counter, then
   the parameters, then a line for the gripper (opening, object, contact,
   step pulses requested, missed, blocked, pull-out rate, its two lines,
   and where a placed part is).
   With a lock-step role (simh/lockstep_dev.c: the five machines) this
   simulator's own plant stands still and SET and SHOW act on the one plant
   the coordinator steps: a setting is checked at once and applied at the
   next quantum boundary; SHOW shows that plant at the last boundary.
   Refused there, with why: GRIPPER (none among the five), HINT (this
   console's hint watches this machine's D/A writes; the 11/03s make them),
   ATTACH PLANT (the trace is the coordinator's).
   SHOW PLANT LAYOUT (only when named), for programs: the row's columns, then
   per axis its letter, display unit, counts per unit and end stops:
     columns time_s,axis,dac,vcmd,vel,pos,counter,grip,contact,missed
     axis X in 800 -9600 9600
   ATTACH PLANT file.csv: writes the trace (truncating the file), DETACH
   PLANT closes it. The plant's row (plant_dev_write_row, also the LAB
   device's P rows): time_s,axis,dac,vcmd,vel,pos,counter (simulated
   seconds, X/Y/Z/T, code, counts/s, counts/s, counts, counter as a signed
   16-bit number), then the gripper's state on every row, whatever the axis:
   grip (opening, inches), contact (0/1), missed (step pulses missed so far). A row for all four axes at every sample (SAMPLE per second,
   at exact instruction counts from the ATTACH) and a row for the axis written
   at every DAC write. Same program, same trace, byte for byte. */
#include "devices.h"

#include <errno.h>
#include <math.h>

#define DEFAULT_SEED   1983
#define DEFAULT_SAMPLE 60

plant robot_plant;
gripper robot_gripper;
#define SEL_GRIPPER PLANT_AXES
static int sel_axis = -1;               /* axis (or SEL_GRIPPER) named earlier in this SET command */
static int32 sample_hz = DEFAULT_SAMPLE;
static clock_series samples_due;         /* the trace's sample series (time_base.c) */
static void (*lines_changed) (void);    /* the bus device whose REQ lines the plant drives */

static t_stat plant_svc (UNIT *uptr);
static t_stat plant_reset (DEVICE *dptr);
static t_stat plant_attach (UNIT *uptr, char *cptr);
static t_stat plant_detach (UNIT *uptr);
static t_stat plant_select (UNIT *uptr, int32 axis, char *cptr, void *desc);
static t_stat plant_set (UNIT *uptr, int32 which, char *cptr, void *desc);
static t_stat plant_set_gripper (UNIT *uptr, int32 which, char *cptr, void *desc);
static t_stat plant_set_seed (UNIT *uptr, int32 val, char *cptr, void *desc);
static t_stat plant_set_sample (UNIT *uptr, int32 val, char *cptr, void *desc);
static t_stat plant_set_power_switch (UNIT *uptr, int32 val, char *cptr, void *desc);
static const char *power_setting (int on);
static t_stat plant_show_global (FILE *st, UNIT *uptr, int32 val, void *desc);
static t_stat plant_show_axes (FILE *st, UNIT *uptr, int32 val, void *desc);
static t_stat plant_show_layout (FILE *st, UNIT *uptr, int32 val, void *desc);

enum { G_OBJECT, G_PULLOUT, G_OPENING, G_PARTX, G_PARTY, G_PARTZ };
static const char *const gripper_param_names[] = {
    "OBJECT", "PULLOUT", "OPENING", "PARTX", "PARTY", "PARTZ"
};

static UNIT plant_unit = { UDATA (&plant_svc, UNIT_ATTABLE, 0) };

#define PARAM(p) { MTAB_XTD|MTAB_VDV, p, NULL, #p + 2, &plant_set, NULL, NULL }
static MTAB plant_mod[] = {
    /* the axis letters first: "T" must select an axis before it can match TAU */
    { MTAB_XTD|MTAB_VDV, AXIS_X, NULL, "X", &plant_select, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, AXIS_Y, NULL, "Y", &plant_select, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, AXIS_Z, NULL, "Z", &plant_select, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, AXIS_T, NULL, "T", &plant_select, NULL, NULL },
    PARAM (P_KV), PARAM (P_TAU), PARAM (P_AMAX), PARAM (P_VMAX), PARAM (P_OFFSET),
    PARAM (P_PMIN), PARAM (P_PMAX), PARAM (P_WALK), PARAM (P_POS),
    { MTAB_XTD|MTAB_VDV, SEL_GRIPPER, NULL, "GRIPPER", &plant_select, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, G_OBJECT, NULL, "OBJECT", &plant_set_gripper, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, G_PULLOUT, NULL, "PULLOUT", &plant_set_gripper, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, G_OPENING, NULL, "OPENING", &plant_set_gripper, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, G_PARTX, NULL, "PARTX", &plant_set_gripper, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, G_PARTY, NULL, "PARTY", &plant_set_gripper, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, G_PARTZ, NULL, "PARTZ", &plant_set_gripper, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, 0, NULL, "SEED", &plant_set_seed, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, 0, NULL, "SAMPLE", &plant_set_sample, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, 0, NULL, "POWER", &plant_set_power_switch, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, 1, NULL, "HINT", &plant_set_power_switch, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, 0, "SETTINGS", NULL, NULL, &plant_show_global, NULL },
    { MTAB_XTD|MTAB_VUN, 0, "AXES", NULL, NULL, &plant_show_axes, NULL },
    { MTAB_XTD|MTAB_VDV|MTAB_NMO, 0, "LAYOUT", NULL, NULL, &plant_show_layout, NULL },
    { 0 }
};

DEVICE plant_dev = {
    "PLANT", &plant_unit, NULL, plant_mod,
    1, 10, 31, 1, 10, 8,
    NULL, NULL, &plant_reset,
    NULL, &plant_attach, &plant_detach,
    NULL, 0
};

void plant_dev_init (void)
{
    plant_init (&robot_plant, DEFAULT_SEED);
    gripper_init (&robot_gripper);
}

/* The hand where the FORTH sees it: each axis's counter reading, unwrapped. */
static void hand_position (double hand[3])
{
    for (int i = 0; i < 3; i++) {
        const plant_axis *a = &robot_plant.ax[i];
        hand[i] = a->run ? a->p - a->p0 : a->p;
    }
}

void plant_dev_catch_up (void)
{
    double hand[3];
    plant_advance (&robot_plant, clock_time ());
    if (robot_gripper.part) {                    /* only a placed part cares where the hand is */
        hand_position (hand);
        gripper_hand_at (&robot_gripper, hand);
    }
}

void plant_dev_on_lines_changed (void (*hook) (void))
{
    lines_changed = hook;
}

void plant_dev_write_row (FILE *f, int axis)
{
    plant_row_write (f, &robot_plant, &robot_gripper, axis);
}

static void trace_row (int axis)
{
    plant_dev_write_row (plant_unit.fileref, axis);
}

/* With a lock-step role the bus devices reach the coordinator's plant
   (simh/lockstep_dev.c) and this one stands still. */
void plant_dev_dac (int axis, int code)
{
    if (lockstep_role != LOCKSTEP_NONE) {
        lockstep_dac (axis, code);
        return;
    }
    plant_dev_catch_up ();
    plant_set_code (&robot_plant, axis, code);
    if (plant_unit.flags & UNIT_ATT)
        trace_row (axis);
    rack_hint_dac (axis, code, robot_plant.power,
                   code - 2048 - plant_offset (&robot_plant, axis));
}

void plant_dev_run_lines (int lines)
{
    if (lockstep_role != LOCKSTEP_NONE) {
        lockstep_run_lines (lines);
        return;
    }
    plant_dev_catch_up ();
    for (int i = 0; i < PLANT_AXES; i++)
        plant_set_run (&robot_plant, i, (lines >> i) & 1);
}

void plant_dev_gripper_lines (int step, int dir)
{
    if (lockstep_role != LOCKSTEP_NONE)
        return;                                  /* no gripper among the five machines */
    plant_dev_catch_up ();
    gripper_lines (&robot_gripper, clock_time (), step, dir);
}

int plant_dev_gripper_contact (void)
{
    return gripper_contact (&robot_gripper);
}

uint16 plant_dev_counter (int axis)
{
    if (lockstep_role != LOCKSTEP_NONE)
        return lockstep_counter ();
    plant_dev_catch_up ();
    return plant_counter (&robot_plant, axis);
}

void plant_dev_rate_changing (int32 old_rate)  /* still in the old time */
{
    plant_dev_catch_up ();
}

void plant_dev_rate_changed (int32 old_rate)
{
    clock_series_rescale (&plant_unit, &samples_due, old_rate);
}

void plant_dev_command_done (void)
{
    sel_axis = -1;
}

static void schedule_sample (void)
{
    sim_cancel (&plant_unit);
    clock_series_start (&samples_due);
    if ((plant_unit.flags & UNIT_ATT) && sample_hz > 0)
        clock_series_next (&plant_unit, &samples_due, sample_hz);
}

static t_stat plant_svc (UNIT *uptr)
{
    if (!(uptr->flags & UNIT_ATT) || sample_hz == 0)
        return SCPE_OK;
    plant_dev_catch_up ();
    for (int i = 0; i < PLANT_AXES; i++)
        trace_row (i);
    clock_series_next (uptr, &samples_due, sample_hz);
    return SCPE_OK;
}

static t_stat plant_reset (DEVICE *dptr)    /* bus INIT does not move the robot */
{
    if ((plant_unit.flags & UNIT_ATT) && sample_hz > 0 && !sim_is_active (&plant_unit))
        schedule_sample ();
    return SCPE_OK;
}

static t_stat plant_attach (UNIT *uptr, char *cptr)
{
    t_stat r;
    if (lockstep_role != LOCKSTEP_NONE) {
        printf ("PLANT: among the five machines the trace is the coordinator's "
                "(make run CONTROLLERS=4 TRACE=file)\n");
        return SCPE_ARG;
    }
    if (uptr->flags & UNIT_ATT)
        plant_detach (uptr);
    if ((r = device_attach_text (uptr, cptr, "PLANT: cannot write the trace")) != SCPE_OK)
        return r;
    fprintf (uptr->fileref, "%s\n", plant_row_columns);
    plant_dev_catch_up ();
    schedule_sample ();
    return SCPE_OK;
}

static t_stat plant_detach (UNIT *uptr)
{
    if (!(uptr->flags & UNIT_ATT))
        return SCPE_OK;
    sim_cancel (uptr);
    device_detach_text (uptr);
    return SCPE_OK;
}

static int parse_number (const char *s, double *x)
{
    char *end;
    if (s == NULL || *s == 0) return 0;
    *x = strtod (s, &end);
    return *end == 0;
}

static t_stat plant_select (UNIT *uptr, int32 axis, char *cptr, void *desc)
{
    if (cptr) {
        printf ("PLANT: an axis letter or GRIPPER takes no value (SET PLANT X TAU=20)\n");
        return SCPE_ARG;
    }
    if (axis == SEL_GRIPPER && lockstep_role != LOCKSTEP_NONE) {
        printf ("PLANT: no gripper among the five machines (docs/controllers.md): nothing to set\n");
        return SCPE_ARG;
    }
    sel_axis = axis;
    return SCPE_OK;
}

/* A setting for the plant: this simulator's own, at once, or with a lock-step
   role the coordinator's, at the next boundary. NULL, or why not (nothing
   changed). */
static const char *apply_setting (const plant_command *c)
{
    const char *why;
    if (lockstep_role != LOCKSTEP_NONE)
        return lockstep_plant_command (c);
    if (c->kind == PC_SAMPLE) {                 /* the trace's, not the plant's */
        if ((why = plant_command_apply (&robot_plant, c)) != NULL)
            return why;
        sample_hz = (int32) c->value;
        schedule_sample ();
        return NULL;
    }
    plant_dev_catch_up ();                       /* what happened so far, with the old state */
    return plant_command_apply (&robot_plant, c);
}

static t_stat refused (const char *why)
{
    if (why == NULL)
        return SCPE_OK;
    printf ("PLANT: %s\n", why);
    return SCPE_ARG;
}

static t_stat plant_set (UNIT *uptr, int32 which, char *cptr, void *desc)
{
    double x;
    const char *why;
    plant_command c = { PC_PARAM, 0, 0, 0, 0.0, 0 };
    if (sel_axis == SEL_GRIPPER) {
        printf ("PLANT: %s is an axis parameter; the gripper has OBJECT, PULLOUT and OPENING\n",
                plant_param_names[which]);
        return SCPE_ARG;
    }
    if (sel_axis < 0) {
        printf ("PLANT: name the axis (X, Y, Z or T) before %s, e.g. SET PLANT X %s=...\n",
                plant_param_names[which], plant_param_names[which]);
        return SCPE_ARG;
    }
    if (!parse_number (cptr, &x)) {
        printf ("PLANT: %s needs a number, e.g. SET PLANT %c %s=20\n", plant_param_names[which],
                plant_axis_names[sel_axis], plant_param_names[which]);
        return SCPE_ARG;
    }
    c.axis = (uint32_t) sel_axis;
    c.which = (uint32_t) which;
    c.value = x;
    if ((why = apply_setting (&c)) != NULL) {
        printf ("PLANT %c: %s\n", plant_axis_names[sel_axis], why);
        return SCPE_ARG;
    }
    return SCPE_OK;
}

static t_stat plant_set_gripper (UNIT *uptr, int32 which, char *cptr, void *desc)
{
    double x;
    const char *why;
    int contact = gripper_contact (&robot_gripper);
    if (sel_axis != SEL_GRIPPER) {
        printf ("PLANT: %s belongs to the gripper: SET PLANT GRIPPER %s=...\n",
                gripper_param_names[which], gripper_param_names[which]);
        return SCPE_ARG;
    }
    if (!parse_number (cptr, &x)) {
        printf ("PLANT: %s needs a number, e.g. SET PLANT GRIPPER %s=1\n",
                gripper_param_names[which], gripper_param_names[which]);
        return SCPE_ARG;
    }
    plant_dev_catch_up ();
    why = which == G_OBJECT ? gripper_set_object (&robot_gripper, x)
        : which == G_PULLOUT ? gripper_set_pullout (&robot_gripper, x)
        : which == G_OPENING ? gripper_set_opening (&robot_gripper, x)
        : gripper_place_part (&robot_gripper, which - G_PARTX, x);
    if (why != NULL) {
        printf ("PLANT GRIPPER: %s\n", why);
        return SCPE_ARG;
    }
    plant_dev_catch_up ();                      /* the part may be at the hand */
    if (gripper_contact (&robot_gripper) != contact && lines_changed)
        lines_changed ();                       /* the contact switch is REQ B */
    return SCPE_OK;
}

static t_stat plant_set_seed (UNIT *uptr, int32 val, char *cptr, void *desc)
{
    char *end;
    unsigned long long s;
    plant_command c = { PC_SEED, 0, 0, 0, 0.0, 0 };
    if (cptr == NULL || *cptr == 0 || *cptr == '-' ||
        (errno = 0, s = strtoull (cptr, &end, 10), *end != 0) || errno) {
        printf ("PLANT: SEED needs a whole number >= 0\n");
        return SCPE_ARG;
    }
    c.seed = (uint64_t) s;
    return refused (apply_setting (&c));
}

static t_stat plant_set_sample (UNIT *uptr, int32 val, char *cptr, void *desc)
{
    char *end;
    long n = -1;                                /* no number: plant_command_apply says why */
    plant_command c = { PC_SAMPLE, 0, 0, 0, 0.0, 0 };
    if (cptr != NULL && *cptr != 0 && (n = strtol (cptr, &end, 10), *end != 0))
        n = -1;
    c.value = (double) n;
    return refused (apply_setting (&c));
}

static t_stat plant_set_power_switch (UNIT *uptr, int32 val, char *cptr, void *desc)
{
    int on;
    if (cptr != NULL && strcmp (cptr, "ON") == 0)
        on = 1;
    else if (cptr != NULL && strcmp (cptr, "OFF") == 0)
        on = 0;
    else {
        printf (val ? "PLANT: HINT is ON or OFF (a line when a move waits on the rack switched off)\n"
                    : "PLANT: POWER is ON or OFF (the amplifier rack's switch)\n");
        return SCPE_ARG;
    }
    if (!val)
        return refused (power_setting (on));
    if (lockstep_role != LOCKSTEP_NONE) {       /* SET PLANT HINT (rack_hint.c) */
        printf ("PLANT: no HINT among the five machines (the 11/03s write the D/As); "
                "SHOW PLANT gives the rack's power\n");
        return SCPE_ARG;
    }
    rack_hint_enable (on);
    return SCPE_OK;
}

static const char *power_setting (int on)
{
    plant_command c = { PC_POWER, 0, 0, 0, on ? 1.0 : 0.0, 0 };
    return apply_setting (&c);
}

void plant_dev_power (int on)
{
    const char *why = power_setting (on);
    if (why != NULL)
        printf ("PLANT: %s\n", why);
}

/* The plant SHOW describes: this simulator's (as last caught up); or the
   coordinator's at the last boundary, with this member's settings still to
   come (their number). */
static const plant *shown (plant *scratch, int *hz, int *to_come)
{
    if (lockstep_role != LOCKSTEP_NONE) {
        *to_come = lockstep_plant_shown (scratch, hz);
        return scratch;
    }
    *hz = sample_hz;
    *to_come = 0;
    return &robot_plant;
}

int plant_dev_powered (void)
{
    plant scratch;
    int hz, to_come;
    return shown (&scratch, &hz, &to_come)->power;
}

static t_stat plant_show_global (FILE *st, UNIT *uptr, int32 val, void *desc)
{
    plant scratch;
    int hz, to_come;
    const plant *pl = shown (&scratch, &hz, &to_come);
    fprintf (st, "seed=%llu, sample=%d/s, power=%s, time=%.6fs", (unsigned long long) pl->seed,
             hz, pl->power ? "on" : "off", lockstep_role != LOCKSTEP_NONE ? pl->now : clock_time ());
    if (lockstep_role != LOCKSTEP_NONE)
        fprintf (st, "\n  (the lock-step coordinator's plant at its last boundary%s)",
                 to_come ? "; the SETs typed since shown, applied at the next" : "");
    return SCPE_OK;
}

static t_stat plant_show_layout (FILE *st, UNIT *uptr, int32 val, void *desc)
{
    plant scratch;
    int hz, to_come;
    const plant *pl = shown (&scratch, &hz, &to_come);
    fprintf (st, "columns %s\n", plant_row_columns);
    for (int i = 0; i < PLANT_AXES; i++)
        fprintf (st, "axis %c %s %.9g %.9g %.9g\n", plant_axis_names[i], plant_unit_name (i),
                 plant_counts_per_unit (i), plant_get_param (pl, i, P_PMIN),
                 plant_get_param (pl, i, P_PMAX));
    return SCPE_OK;
}

static t_stat plant_show_axes (FILE *st, UNIT *uptr, int32 val, void *desc)
{
    plant scratch;
    int hz, to_come;
    const plant *pl;
    if (lockstep_role == LOCKSTEP_NONE)
        plant_dev_catch_up ();
    pl = shown (&scratch, &hz, &to_come);
    /* under 80 columns a line: SHOW PLANT is read on 80-column terminals and the lab page */
    fprintf (st, "\n  ax  pos(counts) position     vel(c/s) dac  vcmd(c/s) offset stop run counter");
    for (int i = 0; i < PLANT_AXES; i++) {
        const plant_axis *a = &pl->ax[i];
        int stop = plant_at_stop (pl, i);
        fprintf (st, "\n  %c %12.3f %8.4f %-3s %9.3f %04d %10.3f %7.3f %-5s %d %6d",
                 plant_axis_names[i], a->p, a->p / plant_counts_per_unit (i), plant_unit_name (i),
                 a->v, a->code, plant_vcmd (pl, i), plant_offset (pl, i),
                 stop > 0 ? "upper" : (stop < 0 ? "lower" : "-"), a->run,
                 (int) (int16) plant_counter (pl, i));
    }
    fprintf (st, "\n  axis  KV        TAU(ms)  AMAX       VMAX      PMIN       PMAX       WALK");
    for (int i = 0; i < PLANT_AXES; i++)
        fprintf (st, "\n  %c     %-9g %-8g %-10g %-9g %-10g %-10g %g", plant_axis_names[i],
                 plant_get_param (pl, i, P_KV), plant_get_param (pl, i, P_TAU),
                 plant_get_param (pl, i, P_AMAX), plant_get_param (pl, i, P_VMAX),
                 plant_get_param (pl, i, P_PMIN), plant_get_param (pl, i, P_PMAX),
                 plant_get_param (pl, i, P_WALK));
    if (lockstep_role != LOCKSTEP_NONE) {
        fprintf (st, "\n  gripper  none among the five machines");
        return SCPE_OK;
    }
    fprintf (st, "\n  gripper  opening %.2f in (%d steps), object %.3f in, contact %d,"
             "\n           pulses %lu, missed %lu, blocked %lu, pullout %g steps/s, step %d dir %d",
             gripper_opening (&robot_gripper), robot_gripper.steps, robot_gripper.object_in,
             gripper_contact (&robot_gripper), robot_gripper.pulses, robot_gripper.missed,
             robot_gripper.blocked, robot_gripper.pullout, robot_gripper.step_line,
             robot_gripper.dir_line);
    if (robot_gripper.part)
        fprintf (st, ",\n           part at %.0f %.0f %.0f%s", robot_gripper.part_at[0],
                 robot_gripper.part_at[1], robot_gripper.part_at[2],
                 gripper_contact (&robot_gripper) ? " (held)" : "");
    return SCPE_OK;
}
