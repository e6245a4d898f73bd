/* plant.c: the axis physics declared in plant.h (model and units there). */
#include "plant.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

const char *const plant_param_names[P_COUNT] = {
    "KV", "TAU", "AMAX", "VMAX", "OFFSET", "PMIN", "PMAX", "WALK", "POS"
};
const char plant_axis_names[PLANT_AXES] = { 'X', 'Y', 'Z', 'T' };

/* docs/design.md section 3 defaults. vmax: 3000 rpm = 40 000 counts/s, the
   amplifier's full scale (Kv * 2048). walk: chosen by this project, small
   enough that drift stays within a code or two over an hour. */
static const struct { double tau_ms, amax, offset, pmin, pmax; } defaults[PLANT_AXES] = {
    { 20.0, 160000.0,  3.0,  -9600.0,  9600.0 },
    { 20.0, 160000.0, -2.0,  -7200.0,  7200.0 },
    { 15.0, 120000.0, 45.0,  -4000.0,  2400.0 },
    { 10.0, 160000.0,  0.6, -12000.0, 12000.0 },
};
#define DEFAULT_KV   19.53
#define DEFAULT_VMAX 40000.0
#define DEFAULT_WALK 0.02

/* splitmix64: small, fast, and the same on every host */
static uint64_t next_u64 (uint64_t *s)
{
    uint64_t z = (*s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static double uniform_open (uint64_t *s)        /* in (0, 1) */
{
    return ((double) (next_u64 (s) >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}

static double normal (uint64_t *s)              /* Box-Muller, one draw */
{
    double u1 = uniform_open (s), u2 = uniform_open (s);
    return sqrt (-2.0 * log (u1)) * cos (6.283185307179586 * u2);
}

void plant_reseed (plant *pl, uint64_t seed)
{
    pl->seed = seed;
    for (int i = 0; i < PLANT_AXES; i++)
        pl->ax[i].rng = seed * 4 + (uint64_t) i;
}

void plant_init (plant *pl, uint64_t seed)
{
    memset (pl, 0, sizeof *pl);                 /* padding too: states compare with memcmp */
    for (int i = 0; i < PLANT_AXES; i++) {
        plant_axis *a = &pl->ax[i];
        a->kv = DEFAULT_KV;
        a->tau_s = defaults[i].tau_ms / 1000.0;
        a->amax = defaults[i].amax;
        a->vmax = DEFAULT_VMAX;
        a->offset_base = defaults[i].offset;
        a->pmin = defaults[i].pmin;
        a->pmax = defaults[i].pmax;
        a->walk = DEFAULT_WALK;
        a->p = a->v = a->w = a->p0 = 0.0;
        a->code = PLANT_CODE_ZERO;
        a->run = 0;
        a->grid_tau = 0.0;
    }
    pl->now = 0.0;
    pl->grid = 0;
    pl->power = 1;
    plant_reseed (pl, seed);
}

double plant_offset (const plant *pl, int axis)
{
    return pl->ax[axis].offset_base + pl->ax[axis].w;
}

double plant_vcmd (const plant *pl, int axis)
{
    const plant_axis *a = &pl->ax[axis];
    double vc = a->kv * ((double) (a->code - PLANT_CODE_ZERO) - plant_offset (pl, axis));
    if (!pl->power)
        return 0.0;                              /* no drive, z's brake on */
    return vc > a->vmax ? a->vmax : (vc < -a->vmax ? -a->vmax : vc);
}

/* expm1(-dt/tau); a whole grid step (the common case) is computed once per tau. */
static double decay_m1 (plant_axis *a, double dt)
{
    if (dt != PLANT_GRID_S)
        return expm1 (-dt / a->tau_s);
    if (a->grid_tau != a->tau_s) {
        a->grid_tau = a->tau_s;
        a->grid_em1 = expm1 (-PLANT_GRID_S / a->tau_s);
    }
    return a->grid_em1;
}

/* Exact solution of the lag over dt from (p, v) with vc fixed, no stops. */
static void lag (plant_axis *a, double vc, double *pp, double *vp, double dt)
{
    double p = *pp, v = *vp, e = vc - v;
    double limit = a->amax * a->tau_s;          /* |vc - v| above this: current-limited */

    if (fabs (e) > limit) {
        double s = e > 0 ? 1.0 : -1.0;
        double t1 = (fabs (e) - limit) / a->amax;
        double tl = dt < t1 ? dt : t1;
        p += v * tl + 0.5 * s * a->amax * tl * tl;
        v += s * a->amax * tl;
        dt -= tl;
        e = (dt > 0.0) ? s * limit : vc - v;    /* exact at the phase change */
    }
    if (dt > 0.0 && e == 0.0) {                  /* settled: v == vc exactly */
        p += vc * dt;
    } else if (dt > 0.0) {
        double m1 = decay_m1 (a, dt);            /* exp(-dt/tau) - 1 */
        p += vc * dt + e * a->tau_s * m1;        /* integral of vc - e*exp(-t/tau) */
        v = vc - e * (m1 + 1.0);
    }
    *pp = p;
    *vp = v;
}

/* Which stop p lies beyond: +1 upper, -1 lower, 0 inside. */
static int beyond (const plant_axis *a, double p)
{
    return p > a->pmax ? 1 : (p < a->pmin ? -1 : 0);
}

/* One event-free interval: the lag, and the end stops. v moves monotonically
   towards vc, so p has at most one turning point and crosses a stop at most
   once: bisection finds the moment of impact; from there the axis sits at the
   stop with v = 0 while vc pushes outward, or leaves it from rest. */
static void axis_step (plant *pl, int axis, double dt)
{
    plant_axis *a = &pl->ax[axis];
    double vc = plant_vcmd (pl, axis);
    double p = a->p, v = a->v;
    int side = plant_at_stop (pl, axis);

    if (side != 0 && v == 0.0 && vc * side >= 0.0)
        return;                                  /* stalled against the stop */
    lag (a, vc, &p, &v, dt);
    if ((side = beyond (a, p)) != 0) {
        double lo = 0.0, hi = dt, stop = side > 0 ? a->pmax : a->pmin;
        for (int i = 0; i < 60 && hi - lo > 1e-12; i++) {
            double mid = 0.5 * (lo + hi), pm = a->p, vm = a->v;
            lag (a, vc, &pm, &vm, mid);
            if (beyond (a, pm) == side) hi = mid; else lo = mid;
        }
        p = stop;
        v = 0.0;
        if (vc * side < 0.0) {                   /* pulled back inward: leave from rest */
            lag (a, vc, &p, &v, dt - hi);
            if (beyond (a, p) != 0) { p = stop; v = 0.0; }
        }
    }
    a->p = p;
    a->v = v;
}

static void walk_step (plant_axis *a)
{
    if (a->walk > 0.0)
        a->w += a->walk * sqrt (PLANT_GRID_S * PLANT_WALK_STEPS) * normal (&a->rng);
}

static void step_all (plant *pl, double dt)
{
    if (dt <= 0.0) return;
    for (int i = 0; i < PLANT_AXES; i++)
        axis_step (pl, i, dt);
}

void plant_advance (plant *pl, double t)
{
    if (!(t > pl->now)) return;                 /* time never runs backwards */
    for (;;) {
        double tg = (double) (pl->grid + 1) * PLANT_GRID_S;
        if (tg > t) break;
        /* on the grid, a step is exactly PLANT_GRID_S (the cached case) */
        step_all (pl, pl->now == (double) pl->grid * PLANT_GRID_S ? PLANT_GRID_S : tg - pl->now);
        pl->now = tg;
        pl->grid++;
        if (pl->grid % PLANT_WALK_STEPS == 0)
            for (int i = 0; i < PLANT_AXES; i++)
                walk_step (&pl->ax[i]);
    }
    step_all (pl, t - pl->now);
    pl->now = t;
}

void plant_set_code (plant *pl, int axis, int code)
{
    pl->ax[axis].code = code & 07777;
}

void plant_set_run (plant *pl, int axis, int run)
{
    plant_axis *a = &pl->ax[axis];
    if (run && !a->run)
        a->p0 = a->p;
    a->run = run ? 1 : 0;
}

void plant_set_power (plant *pl, int on)
{
    pl->power = on ? 1 : 0;
}

uint16_t plant_counter (const plant *pl, int axis)
{
    const plant_axis *a = &pl->ax[axis];
    if (!a->run) return 0;
    return (uint16_t) ((int64_t) floor (a->p - a->p0) & 0xFFFF);
}

int plant_at_stop (const plant *pl, int axis)
{
    const plant_axis *a = &pl->ax[axis];
    return a->p >= a->pmax ? 1 : (a->p <= a->pmin ? -1 : 0);
}

double plant_get_param (const plant *pl, int axis, plant_param which)
{
    const plant_axis *a = &pl->ax[axis];
    switch (which) {
    case P_KV: return a->kv;
    case P_TAU: return a->tau_s * 1000.0;
    case P_AMAX: return a->amax;
    case P_VMAX: return a->vmax;
    case P_OFFSET: return plant_offset (pl, axis);
    case P_PMIN: return a->pmin;
    case P_PMAX: return a->pmax;
    case P_WALK: return a->walk;
    case P_POS: return a->p;
    default: return NAN;
    }
}

#define BIG 1e9                                   /* keeps every product finite */

const char *plant_set_param (plant *pl, int axis, plant_param which, double x)
{
    plant_axis *a;
    if (axis < 0 || axis >= PLANT_AXES) return "no such axis";
    a = &pl->ax[axis];
    if (!isfinite (x) || fabs (x) > BIG) return "value must be a finite number below 1e9";
    switch (which) {
    case P_KV:
        if (x <= 0.0) return "KV must be positive";
        a->kv = x; break;
    case P_TAU:
        if (x <= 0.0) return "TAU (ms) must be positive";
        a->tau_s = x / 1000.0; break;
    case P_AMAX:
        if (x <= 0.0) return "AMAX must be positive";
        a->amax = x; break;
    case P_VMAX:
        if (x <= 0.0) return "VMAX must be positive";
        a->vmax = x; break;
    case P_OFFSET:
        if (fabs (x) > 2048.0) return "OFFSET must lie within +-2048 codes";
        a->offset_base = x; a->w = 0.0; break;
    case P_PMIN:
        if (x >= a->pmax) return "PMIN must lie below PMAX";
        if (x > a->p) return "PMIN must not lie above the present position";
        a->pmin = x; break;
    case P_PMAX:
        if (x <= a->pmin) return "PMAX must lie above PMIN";
        if (x < a->p) return "PMAX must not lie below the present position";
        a->pmax = x; break;
    case P_WALK:
        if (x < 0.0 || x > 1000.0) return "WALK must lie within 0..1000";
        a->walk = x; break;
    case P_POS:
        if (x < a->pmin || x > a->pmax) return "POS must lie within PMIN..PMAX";
        a->p = x; a->v = 0.0;                    /* moved by hand: a running counter counts it */
        break;
    default:
        return "no such parameter";
    }
    return NULL;
}

double plant_counts_per_unit (int axis)
{
    return axis == AXIS_T ? 16000.0 / 360.0 : 800.0;
}

const char *plant_unit_name (int axis)
{
    return axis == AXIS_T ? "deg" : "in";
}
