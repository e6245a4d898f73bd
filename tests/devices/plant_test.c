/* plant_test.c: the axis physics (plant.c) tested alone, against closed-form
   answers. Prints one line per check; exits non-zero if any fails. Built by
   make as build/plant_test and run from tests/devices/test_plant_unit.py. */
#include "plant.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static int failures, checks;

static void check (int ok, const char *what, double got, double want)
{
    checks++;
    if (!ok) failures++;
    printf ("%s %s: got %.6g, expected %.6g\n", ok ? "ok  " : "FAIL", what, got, want);
}

static int near (double got, double want, double rel)
{
    return fabs (got - want) <= rel * fabs (want) + 1e-9;
}

static plant quiet_plant (void)           /* no drift, no offsets: pure dynamics */
{
    plant pl;
    plant_init (&pl, 1);
    for (int i = 0; i < PLANT_AXES; i++) {
        plant_set_param (&pl, i, P_WALK, 0.0);
        plant_set_param (&pl, i, P_OFFSET, 0.0);
    }
    return pl;
}

/* Small step (well under the current limit): v and p follow the exact lag. */
static void test_step_response (void)
{
    for (int ax = 0; ax < PLANT_AXES; ax++) {
        plant pl = quiet_plant ();
        double tau = plant_get_param (&pl, ax, P_TAU) / 1000.0;
        double vc = 19.53 * 50;       /* code 2098: under amax*tau on every axis */
        plant_set_code (&pl, ax, 2098);
        for (int k = 1; k <= 20; k++) {
            double t = k * 0.005;
            plant_advance (&pl, t);
            double v_exact = vc * (1 - exp (-t / tau));
            double p_exact = vc * (t - tau * (1 - exp (-t / tau)));
            if (!near (pl.ax[ax].v, v_exact, 1e-9) || !near (pl.ax[ax].p, p_exact, 1e-9)) {
                check (0, "step response v", pl.ax[ax].v, v_exact);
                check (0, "step response p", pl.ax[ax].p, p_exact);
                return;
            }
        }
        check (near (pl.ax[ax].v, vc * (1 - exp (-0.1 / tau)), 1e-9),
               "step response at 100 ms, exact lag", pl.ax[ax].v, vc * (1 - exp (-0.1 / tau)));
    }
}

/* Full-scale step: |dv/dt| never above amax, v reaches vmax. */
static void test_accel_limit (void)
{
    plant pl = quiet_plant ();
    double amax = plant_get_param (&pl, AXIS_X, P_AMAX), worst = 0, vprev = 0;
    plant_set_code (&pl, AXIS_X, 4095);
    for (int k = 1; k <= 200; k++) {
        plant_advance (&pl, k * 0.0005);
        double a = (pl.ax[AXIS_X].v - vprev) / 0.0005;
        if (a > worst) worst = a;
        vprev = pl.ax[AXIS_X].v;
    }
    check (worst <= amax * (1 + 1e-9) && worst > 0.99 * amax, "peak acceleration <= amax",
           worst, amax);
    /* during the limited phase the velocity is exactly amax * t */
    plant p2 = quiet_plant ();
    plant_set_code (&p2, AXIS_X, 4095);
    plant_advance (&p2, 0.1);
    check (near (p2.ax[AXIS_X].v, 0.1 * amax, 1e-9), "v = amax t while limited",
           p2.ax[AXIS_X].v, 0.1 * amax);
}

static void test_end_stops (void)
{
    plant pl = quiet_plant ();
    plant_set_code (&pl, AXIS_Z, 4095);          /* push up for 2 s */
    plant_advance (&pl, 2.0);
    check (pl.ax[AXIS_Z].p == 2400.0 && pl.ax[AXIS_Z].v == 0.0, "upper stop holds", pl.ax[AXIS_Z].p, 2400);
    check (plant_at_stop (&pl, AXIS_Z) == 1, "at upper stop flag", plant_at_stop (&pl, AXIS_Z), 1);
    plant_set_code (&pl, AXIS_Z, 0);
    plant_advance (&pl, 4.0);
    check (pl.ax[AXIS_Z].p == -4000.0 && pl.ax[AXIS_Z].v == 0.0, "lower stop holds", pl.ax[AXIS_Z].p, -4000);
    plant_set_code (&pl, AXIS_Z, 2148);          /* leaves the stop again */
    plant_advance (&pl, 4.2);
    check (pl.ax[AXIS_Z].p > -4000.0 && pl.ax[AXIS_Z].v > 0, "leaves the stop", pl.ax[AXIS_Z].p, -4000);
}

/* The solution is exact between events: reading the state often (every 0.1 ms)
   or rarely (the 1 ms grid only) gives the same motion, stops included. */
static void test_events_do_not_change_the_motion (void)
{
    plant a = quiet_plant (), b = quiet_plant ();
    double worst = 0;
    for (int ax = 0; ax < PLANT_AXES; ax++) {
        plant_set_code (&a, ax, 4095); plant_set_code (&b, ax, 4095);
    }
    for (int k = 1; k <= 10000; k++) {
        plant_advance (&b, k * 0.0001);
        if (k % 10 == 0) {
            plant_advance (&a, k * 0.0001);
            for (int ax = 0; ax < PLANT_AXES; ax++) {
                double d = fabs (a.ax[ax].p - b.ax[ax].p);
                if (d > worst) worst = d;
            }
        }
        if (k == 3000)                           /* both at 0.3 s: turn round */
            for (int ax = 0; ax < PLANT_AXES; ax++) {
                plant_set_code (&a, ax, 1000); plant_set_code (&b, ax, 1000);
            }
    }
    check (worst < 1e-6, "frequent and rare events: same positions (counts)", worst, 0);
    check (b.ax[AXIS_Z].p == -4000.0, "and both reach the stop", b.ax[AXIS_Z].p, -4000);
}

static void test_counter (void)
{
    plant pl = quiet_plant ();
    plant_set_code (&pl, AXIS_T, 2148);          /* +1953 counts/s */
    plant_advance (&pl, 1.0);
    check (plant_counter (&pl, AXIS_T) == 0, "held counter reads 0", plant_counter (&pl, AXIS_T), 0);
    double p_at_run = pl.ax[AXIS_T].p;
    plant_set_run (&pl, AXIS_T, 1);
    plant_advance (&pl, 2.0);
    double want = floor (pl.ax[AXIS_T].p - p_at_run);
    check (plant_counter (&pl, AXIS_T) == (uint16_t) want, "counter = floor(p - p0)",
           plant_counter (&pl, AXIS_T), want);
    plant_set_code (&pl, AXIS_T, 2048 - 200);    /* reverse: count goes below zero */
    plant_advance (&pl, 4.0);
    want = floor (pl.ax[AXIS_T].p - p_at_run);
    check (want < 0 && plant_counter (&pl, AXIS_T) == (uint16_t) ((int) want & 0xFFFF),
           "counter wraps below zero modulo 65536", plant_counter (&pl, AXIS_T), (int) want & 0xFFFF);
    plant_set_run (&pl, AXIS_T, 0);
    check (plant_counter (&pl, AXIS_T) == 0, "run line 0 clears", plant_counter (&pl, AXIS_T), 0);
}

static void test_drift (void)
{
    for (int ax = 0; ax < PLANT_AXES; ax++) {
        plant pl;
        plant_init (&pl, 7);
        plant_set_param (&pl, ax, P_WALK, 0.0);
        double off = plant_offset (&pl, ax), kv = plant_get_param (&pl, ax, P_KV);
        plant_advance (&pl, 1.0);                 /* well past the lag */
        check (near (pl.ax[ax].v, -kv * off, 1e-9), "code 2048 drifts at -Kv*offset",
               pl.ax[ax].v, -kv * off);
    }
}

static void test_determinism_and_walk (void)
{
    plant a, b, c;
    plant_init (&a, 42); plant_init (&b, 42); plant_init (&c, 43);
    for (int k = 1; k <= 600; k++) {
        int code = 2048 + ((k * 37) % 400) - 200;
        for (int ax = 0; ax < PLANT_AXES; ax++) {
            plant_set_code (&a, ax, code); plant_set_code (&b, ax, code); plant_set_code (&c, ax, code);
        }
        plant_advance (&a, k / 60.0); plant_advance (&b, k / 60.0); plant_advance (&c, k / 60.0);
    }
    check (memcmp (&a, &b, sizeof a) == 0, "same seed, same inputs: identical state", 0, 0);
    check (plant_offset (&a, AXIS_X) != plant_offset (&c, AXIS_X), "another seed walks elsewhere",
           plant_offset (&a, AXIS_X), plant_offset (&c, AXIS_X));
    check (fabs (plant_offset (&a, AXIS_X) - 3.0) < 1.0, "walk is slow (10 s: < 1 code)",
           plant_offset (&a, AXIS_X), 3.0);
}

static void test_extremes_stay_finite (void)
{
    plant pl;
    plant_init (&pl, 3);
    plant_set_param (&pl, AXIS_Y, P_TAU, 1e-6);   /* very stiff */
    for (int k = 1; k <= 3000; k++) {
        for (int ax = 0; ax < PLANT_AXES; ax++)
            plant_set_code (&pl, ax, (k * 1237 + ax * 911) & 0xFFFF);
        plant_advance (&pl, k * 0.0007);
    }
    int ok = 1;
    for (int ax = 0; ax < PLANT_AXES; ax++)
        ok &= isfinite (pl.ax[ax].p) && isfinite (pl.ax[ax].v) &&
              pl.ax[ax].p >= pl.ax[ax].pmin && pl.ax[ax].p <= pl.ax[ax].pmax;
    check (ok, "random codes: finite, inside the stops", ok, 1);
}

static void test_power_switch (void)
{
    plant pl;
    plant_init (&pl, 5);
    plant_set_code (&pl, AXIS_X, 2048 + 300);
    plant_advance (&pl, 0.5);                      /* x at full speed, z falling */
    plant_set_power (&pl, 0);
    plant_advance (&pl, 1.0);                      /* 25 time constants: at rest */
    double px = pl.ax[AXIS_X].p, pz = pl.ax[AXIS_Z].p;
    check (plant_vcmd (&pl, AXIS_X) == 0.0 && plant_vcmd (&pl, AXIS_Z) == 0.0,
           "rack off: no axis is commanded", plant_vcmd (&pl, AXIS_Z), 0);
    plant_advance (&pl, 600.0);                    /* ten minutes: z's gravity moves nothing */
    check (fabs (pl.ax[AXIS_X].p - px) < 1e-6 && fabs (pl.ax[AXIS_Z].p - pz) < 1e-6 &&
           fabs (pl.ax[AXIS_Z].v) < 1e-9,
           "rack off: the axes stand still", pl.ax[AXIS_Z].p - pz, 0);
    plant_set_power (&pl, 1);
    plant_advance (&pl, 601.0);
    check (pl.ax[AXIS_X].p > px + 5000.0, "rack on again: x moves at its DAC's command",
           pl.ax[AXIS_X].p - px, 5860);
}

static void test_bad_parameters (void)
{
    plant pl;
    plant_init (&pl, 1);
    plant before = pl;
    int rejected = plant_set_param (&pl, AXIS_X, P_TAU, 0) && plant_set_param (&pl, AXIS_X, P_TAU, -3) &&
        plant_set_param (&pl, AXIS_X, P_KV, NAN) && plant_set_param (&pl, AXIS_X, P_AMAX, INFINITY) &&
        plant_set_param (&pl, AXIS_X, P_PMIN, 20000) && plant_set_param (&pl, 7, P_KV, 1) &&
        plant_set_param (&pl, AXIS_Z, P_POS, 5000);
    check (rejected && memcmp (&pl, &before, sizeof pl) == 0, "bad parameters rejected, state unchanged", rejected, 1);
}

int main (void)
{
    test_step_response ();
    test_accel_limit ();
    test_end_stops ();
    test_events_do_not_change_the_motion ();
    test_counter ();
    test_drift ();
    test_determinism_and_walk ();
    test_extremes_stay_finite ();
    test_power_switch ();
    test_bad_parameters ();
    printf ("%d checks, %d failed\n", checks, failures);
    return failures != 0;
}
