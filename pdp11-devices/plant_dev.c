/* plant_dev.c: SIMH glue for the four-axis plant (SIMH device PLANT). The
   physics is plant.c; this file only connects it to simulated time, the bus
   devices (aav11.c, drv11.c), SET/SHOW and the trace file. No bus registers.

   SET (one axis selected by its letter, then any of its parameters):
     SET PLANT X TAU=20             SET PLANT Z KV=19.53,OFFSET=45
     parameters: KV (counts/s per code), TAU (ms), AMAX (counts/s^2),
     VMAX (counts/s), OFFSET (codes; restarts that axis's walk), PMIN, PMAX
     (end stops, counts), WALK (offset random walk, codes per sqrt(s)),
     POS (counts: puts the axis there at rest; a running counter counts it)
     device-wide: SET PLANT SEED=n (random walk seed, default 1983),
     SET PLANT SAMPLE=n (trace samples per simulated second, 0..1000,
     default 60; 0 = rows at DAC writes only)
   A rejected value (non-number, out of range, no axis selected) prints why,
   returns a SIMH error and leaves that parameter as it was; modifiers are
   applied left to right. The selection lasts until the end of the command.
   SHOW PLANT: per axis position (counts and inches or degrees), velocity,
   DAC code, commanded velocity, offset, end stop, run line, counter, then
   the parameters.
   ATTACH PLANT file.csv: writes the trace (truncating the file), DETACH
   PLANT closes it. Columns: time_s,axis,dac,vcmd,vel,pos,counter (simulated
   seconds, X/Y/Z/T, code, counts/s, counts/s, counts, counter as a signed
   16-bit number). A row for all four axes at every sample (SAMPLE per second,
   at exact instruction counts from the ATTACH) and a row for the axis written
   at every DAC write. Same program, same trace, byte for byte. */
#include "robot.h"

#include <errno.h>
#include <math.h>

#define DEFAULT_SEED   1983
#define DEFAULT_SAMPLE 60
#define SAMPLE_MAX     1000

plant robot_plant;
static int sel_axis = -1;               /* axis named earlier in this SET command */
static int32 sample_hz = DEFAULT_SAMPLE;
static int32 sample_acc;

static t_stat plant_svc (UNIT *uptr);
static t_stat plant_reset (DEVICE *dptr);
static t_stat plant_attach (UNIT *uptr, char *cptr);
static t_stat plant_detach (UNIT *uptr);
static t_stat plant_select (UNIT *uptr, int32 axis, char *cptr, void *desc);
static t_stat plant_set (UNIT *uptr, int32 which, char *cptr, void *desc);
static t_stat plant_set_seed (UNIT *uptr, int32 val, char *cptr, void *desc);
static t_stat plant_set_sample (UNIT *uptr, int32 val, char *cptr, void *desc);
static t_stat plant_show_global (FILE *st, UNIT *uptr, int32 val, void *desc);
static t_stat plant_show_axes (FILE *st, UNIT *uptr, int32 val, void *desc);

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
    { MTAB_XTD|MTAB_VDV, 0, NULL, "SEED", &plant_set_seed, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, 0, NULL, "SAMPLE", &plant_set_sample, NULL, NULL },
    { MTAB_XTD|MTAB_VDV, 0, "SETTINGS", NULL, NULL, &plant_show_global, NULL },
    { MTAB_XTD|MTAB_VUN, 0, "AXES", NULL, NULL, &plant_show_axes, NULL },
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
}

void plant_dev_catch_up (void)
{
    plant_advance (&robot_plant, robot_time ());
}

static void trace_row (int axis)
{
    const plant_axis *a = &robot_plant.ax[axis];
    fprintf (plant_unit.fileref, "%.9f,%c,%d,%.3f,%.3f,%.3f,%d\n", robot_plant.now,
             plant_axis_names[axis], a->code, plant_vcmd (&robot_plant, axis), a->v, a->p,
             (int) (int16) plant_counter (&robot_plant, axis));
}

void plant_dev_dac (int axis, int code)
{
    plant_dev_catch_up ();
    plant_set_code (&robot_plant, axis, code);
    if (plant_unit.flags & UNIT_ATT)
        trace_row (axis);
}

void plant_dev_run_lines (int lines)
{
    plant_dev_catch_up ();
    for (int i = 0; i < PLANT_AXES; i++)
        plant_set_run (&robot_plant, i, (lines >> i) & 1);
}

uint16 plant_dev_counter (int axis)
{
    plant_dev_catch_up ();
    return plant_counter (&robot_plant, axis);
}

void plant_dev_rate_changed (int32 old_rate)
{
    robot_rescale (&plant_unit, old_rate);
    sample_acc = 0;
}

void plant_dev_command_done (void)
{
    sel_axis = -1;
}

static void schedule_sample (void)
{
    sim_cancel (&plant_unit);
    sample_acc = 0;
    if ((plant_unit.flags & UNIT_ATT) && sample_hz > 0)
        sim_activate (&plant_unit, robot_share (sample_hz, &sample_acc));
}

static t_stat plant_svc (UNIT *uptr)
{
    if (!(uptr->flags & UNIT_ATT) || sample_hz == 0)
        return SCPE_OK;
    plant_dev_catch_up ();
    for (int i = 0; i < PLANT_AXES; i++)
        trace_row (i);
    sim_activate (uptr, robot_share (sample_hz, &sample_acc));
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
    if (uptr->flags & UNIT_ATT)
        plant_detach (uptr);
    if ((r = robot_attach_text (uptr, cptr, "PLANT: cannot write the trace")) != SCPE_OK)
        return r;
    fputs ("time_s,axis,dac,vcmd,vel,pos,counter\n", uptr->fileref);
    plant_dev_catch_up ();
    schedule_sample ();
    return SCPE_OK;
}

static t_stat plant_detach (UNIT *uptr)
{
    if (!(uptr->flags & UNIT_ATT))
        return SCPE_OK;
    sim_cancel (uptr);
    robot_detach_text (uptr);
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
        printf ("PLANT: an axis letter takes no value (SET PLANT X TAU=20)\n");
        return SCPE_ARG;
    }
    sel_axis = axis;
    return SCPE_OK;
}

static t_stat plant_set (UNIT *uptr, int32 which, char *cptr, void *desc)
{
    double x;
    const char *why;
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
    plant_dev_catch_up ();
    if ((why = plant_set_param (&robot_plant, sel_axis, (plant_param) which, x)) != NULL) {
        printf ("PLANT %c: %s\n", plant_axis_names[sel_axis], why);
        return SCPE_ARG;
    }
    return SCPE_OK;
}

static t_stat plant_set_seed (UNIT *uptr, int32 val, char *cptr, void *desc)
{
    char *end;
    unsigned long long s;
    if (cptr == NULL || *cptr == 0 || *cptr == '-' ||
        (errno = 0, s = strtoull (cptr, &end, 10), *end != 0) || errno) {
        printf ("PLANT: SEED needs a whole number >= 0\n");
        return SCPE_ARG;
    }
    plant_dev_catch_up ();
    plant_reseed (&robot_plant, (uint64_t) s);
    return SCPE_OK;
}

static t_stat plant_set_sample (UNIT *uptr, int32 val, char *cptr, void *desc)
{
    char *end;
    long n;
    if (cptr == NULL || *cptr == 0 || (n = strtol (cptr, &end, 10), *end != 0) ||
        n < 0 || n > SAMPLE_MAX) {
        printf ("PLANT: SAMPLE needs a whole number of samples per second, 0..%d\n", SAMPLE_MAX);
        return SCPE_ARG;
    }
    sample_hz = (int32) n;
    schedule_sample ();
    return SCPE_OK;
}

static t_stat plant_show_global (FILE *st, UNIT *uptr, int32 val, void *desc)
{
    fprintf (st, "seed=%llu, sample=%d/s, time=%.6fs", (unsigned long long) robot_plant.seed,
             sample_hz, robot_time ());
    return SCPE_OK;
}

static t_stat plant_show_axes (FILE *st, UNIT *uptr, int32 val, void *desc)
{
    plant_dev_catch_up ();
    fprintf (st, "\n  axis  pos(counts)  position      vel(c/s)  dac   vcmd(c/s)  offset   stop   run counter");
    for (int i = 0; i < PLANT_AXES; i++) {
        const plant_axis *a = &robot_plant.ax[i];
        int stop = plant_at_stop (&robot_plant, i);
        fprintf (st, "\n  %c   %11.3f %10.4f %-3s %10.3f  %04d %10.3f %8.3f  %-5s  %d  %6d",
                 plant_axis_names[i], a->p, a->p / plant_counts_per_unit (i), plant_unit_name (i),
                 a->v, a->code, plant_vcmd (&robot_plant, i), plant_offset (&robot_plant, i),
                 stop > 0 ? "upper" : (stop < 0 ? "lower" : "-"), a->run,
                 (int) (int16) plant_counter (&robot_plant, i));
    }
    fprintf (st, "\n  axis  KV        TAU(ms)  AMAX       VMAX      PMIN       PMAX       WALK");
    for (int i = 0; i < PLANT_AXES; i++)
        fprintf (st, "\n  %c     %-9g %-8g %-10g %-9g %-10g %-10g %g", plant_axis_names[i],
                 plant_get_param (&robot_plant, i, P_KV), plant_get_param (&robot_plant, i, P_TAU),
                 plant_get_param (&robot_plant, i, P_AMAX), plant_get_param (&robot_plant, i, P_VMAX),
                 plant_get_param (&robot_plant, i, P_PMIN), plant_get_param (&robot_plant, i, P_PMAX),
                 plant_get_param (&robot_plant, i, P_WALK));
    return SCPE_OK;
}
