/* plant.h: the four axes of the 1983 Cartesian robot (docs/design.md section 3).

   Pure, deterministic physics with no SIMH types, so it can be tested alone
   (plant_test.c). Time is in simulated seconds, positions in encoder counts,
   velocities in counts/s, DAC codes 0..4095 (offset binary, 2048 = 0 V).

   Per axis, state p (counts) and v (counts/s):
     vc = Kv * (code - 2048 - offset), clamped to +-vmax
     dv/dt = (vc - v) / tau, with |dv/dt| bounded by amax (current limit)
     p stays inside [pmin, pmax]; at a stop the motor stalls (v = 0 while it
     pushes outward)
     offset = base + w, w a seeded random walk (walk codes per sqrt(s)),
     stepped every 0.1 s on the fixed grid of simulated time
     counter = floor(p - p0) mod 65536 while the run line is 1 (p0 = p when
     the run line went to 1), 0 while it is 0
   The amplifier rack's power switch (power, on at plant_init): while it is
   off no amplifier drives its motor and z's brake holds, so vc = 0 on every
   axis whatever the DAC says (the offsets, gravity included, move nothing):
   a moving axis slows to rest along the same lag and stays there.

   Between events the lag is solved exactly (constant-acceleration segment
   while the current limit binds, then the exponential); a stop is met at the
   moment of impact (bisection on that solution). Events: every point of a
   fixed 1 ms grid of simulated time (every 100th also steps the walk), and
   whatever the caller adds by advancing to a time (DAC write, counter read,
   trace sample). Default walk 0.02 codes per sqrt(s), seed 1983. */
#ifndef PLANT_H
#define PLANT_H

#include <stdint.h>

#define PLANT_AXES   4
#define PLANT_GRID_S 0.001                 /* simulated seconds per grid step */
#define PLANT_WALK_STEPS 100               /* grid steps per offset-walk step (0.1 s) */
#define PLANT_CODE_ZERO 2048

enum { AXIS_X, AXIS_Y, AXIS_Z, AXIS_T };

/* Settable parameters of one axis; names as in SET PLANT (plant_param_names). */
typedef enum {
    P_KV,        /* counts/s per DAC code */
    P_TAU,       /* velocity-loop time constant, ms */
    P_AMAX,      /* acceleration limit, counts/s^2 */
    P_VMAX,      /* commanded velocity clamp, counts/s */
    P_OFFSET,    /* zero offset, DAC codes (sets the base, restarts the walk) */
    P_PMIN,      /* lower end stop, counts */
    P_PMAX,      /* upper end stop, counts */
    P_WALK,      /* offset random-walk intensity, codes per sqrt(s) */
    P_POS,       /* position, counts (moves the axis there at rest) */
    P_COUNT
} plant_param;

typedef struct {
    double kv, tau_s, amax, vmax, pmin, pmax, walk, offset_base;
    double p, v, w;            /* position, velocity, walk deviation */
    double p0;                 /* position when the run line went to 1 */
    int code;                  /* last DAC code */
    int run;                   /* counter run line */
    uint64_t rng;              /* this axis's random stream */
    double grid_tau, grid_em1; /* cache: expm1(-PLANT_GRID_S / tau) for that tau */
} plant_axis;

typedef struct {
    plant_axis ax[PLANT_AXES];
    double now;                /* simulated seconds the state refers to */
    uint64_t grid;             /* index of the last grid point passed */
    uint64_t seed;
    int power;                 /* amplifier rack switched on */
} plant;

extern const char *const plant_param_names[P_COUNT];
extern const char plant_axis_names[PLANT_AXES];       /* "XYZT" */

void plant_init (plant *pl, uint64_t seed);     /* power-up: DESIGN defaults */
void plant_reseed (plant *pl, uint64_t seed);   /* restart the random streams */
void plant_advance (plant *pl, double t);       /* integrate up to time t */
void plant_set_code (plant *pl, int axis, int code);
void plant_set_run (plant *pl, int axis, int run);
void plant_set_power (plant *pl, int on);       /* the amplifier rack's switch */
uint16_t plant_counter (const plant *pl, int axis);
double plant_vcmd (const plant *pl, int axis);
double plant_offset (const plant *pl, int axis);
int plant_at_stop (const plant *pl, int axis);  /* -1 lower, +1 upper, 0 none */
double plant_get_param (const plant *pl, int axis, plant_param which);
/* Returns NULL when accepted, else a message saying why not (state unchanged). */
const char *plant_set_param (plant *pl, int axis, plant_param which, double value);
/* Units for display: counts per inch (x, y, z) or per degree (t). */
double plant_counts_per_unit (int axis);
const char *plant_unit_name (int axis);

#endif
