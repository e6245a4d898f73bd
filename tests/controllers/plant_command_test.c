/* plant_command_test.c: SET PLANT settings as data, tested alone: applied to
   a plant with plant.c's checks (plant/plant_command.c), and applied by the
   lock-step coordinator at a boundary for every member at once
   (lockstep/quantum.c). One line per check; exits non-zero if any fails.
   Built by make as build/plant_command_test, run from
   tests/controllers/test_plant_command_unit.py. */
#define _POSIX_C_SOURCE 200809L   /* open_memstream */
#include "plant_command.h"
#include "quantum.h"
#include "world_status.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures, checks;

static void check (int ok, const char *what)
{
    checks++;
    if (!ok) failures++;
    printf ("%s %s\n", ok ? "ok  " : "FAIL", what);
}

static plant_command param (int axis, plant_param which, double value)
{
    plant_command c = { PC_PARAM, (uint32_t) axis, (uint32_t) which, 0, value, 0 };
    return c;
}

static plant_command power (int on)
{
    plant_command c = { PC_POWER, 0, 0, 0, on, 0 };
    return c;
}

static void settings_on_a_plant (void)
{
    plant pl, before;
    char text[64];
    plant_command c;
    plant_init (&pl, 1983);
    c = param (AXIS_X, P_TAU, 30);
    check (plant_command_apply (&pl, &c) == NULL && pl.ax[AXIS_X].tau_s == 0.030, "X TAU=30 applied");
    before = pl;
    c = param (AXIS_X, P_TAU, -5);
    check (plant_command_apply (&pl, &c) != NULL && !memcmp (&pl, &before, sizeof pl),
           "X TAU=-5 refused with why, the plant as it was");
    c = param (AXIS_Z, P_PMIN, 5000);
    check (plant_command_apply (&pl, &c) != NULL && !memcmp (&pl, &before, sizeof pl),
           "Z PMIN above PMAX refused");
    c = param (7, P_KV, 1);
    check (plant_command_apply (&pl, &c) != NULL, "no axis 7");
    c = power (0);
    check (plant_command_apply (&pl, &c) == NULL && pl.power == 0, "POWER=OFF switches the rack off");
    c.kind = PC_SEED; c.seed = 42;
    check (plant_command_apply (&pl, &c) == NULL && pl.seed == 42, "SEED=42 reseeds");
    before = pl;
    c.kind = PC_SAMPLE; c.value = 1001;
    check (plant_command_apply (&pl, &c) != NULL, "SAMPLE=1001 refused");
    c.value = 250;
    check (plant_command_apply (&pl, &c) == NULL && !memcmp (&pl, &before, sizeof pl),
           "SAMPLE=250 accepted, the plant untouched (the trace's)");
    c.kind = 99;
    check (plant_command_apply (&pl, &c) != NULL, "an unknown kind refused");
    c = param (AXIS_Z, P_OFFSET, 45);
    plant_command_text (&c, text, sizeof text);
    check (!strcmp (text, "Z OFFSET=45"), "text: Z OFFSET=45");
    c = power (1);
    plant_command_text (&c, text, sizeof text);
    check (!strcmp (text, "POWER=ON"), "text: POWER=ON");
}

/* Two quanta with x's 11/03 driving its D/A; commands[m] for quantum 2. */
static void boundary (ls_world *w, ls_down downs[LS_MEMBERS], int n_main, const plant_command *main,
                      int n_y, const plant_command *y)
{
    ls_up ups[LS_MEMBERS];
    const ls_up *up_ptrs[LS_MEMBERS];
    ls_event drive = { 0.0001, LS_EV_DAC, AXIS_X, 3000, 0 };
    const ls_event *ev_ptrs[LS_MEMBERS] = { &drive, NULL, NULL, NULL, NULL };
    const plant_command *none[LS_MEMBERS] = { NULL, NULL, NULL, NULL, NULL };
    const plant_command *cmd_ptrs[LS_MEMBERS] = { NULL, y, NULL, NULL, main };
    memset (ups, 0, sizeof ups);
    for (int m = 0; m < LS_MEMBERS; m++) { ups[m].quantum = 1; up_ptrs[m] = &ups[m]; }
    ups[0].n_events = 1;
    ls_world_step (w, 1, up_ptrs, ev_ptrs, none, downs);
    for (int m = 0; m < LS_MEMBERS; m++) ups[m].quantum = 2;
    ups[0].n_events = 0;
    ups[LS_MAIN].n_commands = (uint32_t) n_main;
    ups[1].n_commands = (uint32_t) n_y;
    check (ls_world_step (w, 2, up_ptrs, ev_ptrs, cmd_ptrs, downs) >= 0, "quantum 2 stepped");
}

static void settings_at_the_boundary (void)
{
    ls_world w;
    static ls_down downs[LS_MEMBERS];
    char *text = NULL;
    size_t size = 0;
    FILE *trace = open_memstream (&text, &size);
    plant_command main_sets[3] = { power (0), param (AXIS_X, P_PMAX, 5000), param (AXIS_Y, P_TAU, -1) };
    plant_command y_sets[1] = { param (AXIS_X, P_PMIN, 6000) };
    ls_world_init (&w, 1983, 1000, trace);
    boundary (&w, downs, 3, main_sets, 1, y_sets);
    check (downs[0].pl.power == 0 && downs[LS_MAIN].pl.power == 0 && downs[3].pl.power == 0,
           "POWER=OFF from the 11/23 reaches every member's plant at the boundary");
    check (downs[0].pl.now == 0.002, "... the boundary of the quantum it was typed in");
    check (downs[0].pl.ax[AXIS_X].pmax == 5000, "X PMAX=5000 applied");
    check (downs[LS_MAIN].refused == 1 && downs[1].refused == 1 && downs[0].refused == 0,
           "refused where the plant says no: the 11/23's Y TAU=-1, y's PMIN above the new PMAX");
    check (downs[0].pl.ax[AXIS_X].pmin == -9600 && downs[0].pl.ax[AXIS_Y].tau_s == 0.020,
           "a refused setting leaves the plant as it was");
    check (plant_vcmd (&downs[0].pl, AXIS_X) == 0.0, "the rack off: no drive on x");
    fflush (trace);
    /* the quantum's rows were written before the switch: drive in the row at 2 ms */
    const char *at = "\n0.002000000,X,";
    char *row = strstr (text, at);
    check (row != NULL && strtod (strchr (row + strlen (at), ',') + 1, NULL) > 10000,
           "the row at the boundary itself: still driven (the switch comes after it)");
    char *status = world_status (&w, 2);
    check (strstr (status, "\"power\":0") != NULL, "the status says the rack is off");
    free (status);
    fclose (trace);
    free (text);
}

static void sample_rate_at_the_boundary (void)
{
    ls_world w;
    static ls_down downs[LS_MEMBERS];
    char *text = NULL;
    size_t size = 0;
    FILE *trace = open_memstream (&text, &size);
    plant_command sample = { PC_SAMPLE, 0, 0, 0, 500, 0 };
    ls_world_init (&w, 1983, 0, trace);
    boundary (&w, downs, 1, &sample, 0, NULL);
    check (downs[2].sample_hz == 500, "SAMPLE=500 reaches every member");
    ls_up ups[LS_MEMBERS];
    const ls_up *up_ptrs[LS_MEMBERS];
    const ls_event *ev_ptrs[LS_MEMBERS] = { NULL, NULL, NULL, NULL, NULL };
    const plant_command *none[LS_MEMBERS] = { NULL, NULL, NULL, NULL, NULL };
    memset (ups, 0, sizeof ups);
    for (uint64_t k = 3; k <= 6; k++) {
        for (int m = 0; m < LS_MEMBERS; m++) { ups[m].quantum = k; up_ptrs[m] = &ups[m]; }
        ls_world_step (&w, k, up_ptrs, ev_ptrs, none, downs);
    }
    fflush (trace);
    check (strstr (text, "\n0.004000000,X,") && strstr (text, "\n0.006000000,X,")
           && !strstr (text, "\n0.003000000,X,") && !strstr (text, "\n0.005000000,X,"),
           "samples every 2 ms from one period after the boundary (4, 6 ms)");
    fclose (trace);
    free (text);
}

int main (void)
{
    settings_on_a_plant ();
    settings_at_the_boundary ();
    sample_rate_at_the_boundary ();
    printf ("%d checks, %d failed\n", checks, failures);
    return failures != 0;
}
