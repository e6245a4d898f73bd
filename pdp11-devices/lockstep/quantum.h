/* quantum.h: what the lock-step coordinator does at each boundary, as pure
   logic (no sockets; tests/controllers/lockstep_test.c): the one plant,
   stepped here only, and the links' crossing.

   ls_world_step(w, k, ups, events, downs): the members' events of quantum k
   (ups[m] NULL for a member not live) are applied to the plant in time
   order (equal times: member order, then each member's own order), trace
   rows interleaved (a row for the axis at every DAC write, rows for all
   four axes at every sample time i / sample_hz, as the PLANT device
   writes them); the plant is integrated to the boundary k / quanta_per_s;
   each live member's ls_down gets the plant, what its link peers did, and
   the lost 11/03s (expected, no longer live: for the 11/23) or LS_END (for an 11/03 whose 11/23 is
   gone). An event for an axis other than the member's own is ignored: an
   11/03 drives only its axis, the 11/23 none.
   Then, at the boundary, the SET PLANT settings the members sent with their
   ls_up (commands[m], ups[m]->n_commands of them) are applied in member
   order, each with plant_command_apply's checks: any member may set the one
   plant (the rack's power, an axis's parameters, the seed, the trace's
   sample rate); a setting the plant refuses (another member's setting of
   the same quantum came first) changes nothing and counts in that member's
   ls_down.refused. Every member's ls_down carries the plant after them.
   Returns the number of settings applied. */
#ifndef QUANTUM_H
#define QUANTUM_H

#include <stdio.h>

#include "gripper.h"
#include "lockstep_wire.h"

#define LS_HISTORY 8                    /* link words kept per axis and direction */
/* The link protocol's command words (docs/controllers.md "The link protocol"):
   LS_COMMAND_BASE + code, code 1..LS_COMMANDS, each followed by its value. */
#define LS_COMMAND_BASE 0122400
#define LS_COMMANDS 7

typedef struct {                        /* the last words that crossed one way */
    uint16_t word[LS_HISTORY];
    uint64_t quantum[LS_HISTORY];
    int n;                              /* words ever; the newest at (n - 1) % LS_HISTORY */
    /* 11/23 -> 11/03 only: the value last sent with each command, kept however many
       words followed (the eight above are soon status polls only) */
    int pending;                        /* 0, or the command whose value comes next */
    uint16_t value[LS_COMMANDS + 1];
    uint32_t valued;                    /* bit c: value[c] has been sent */
} ls_history;

typedef struct {
    plant pl;
    gripper gr;                 /* not driven in this mode; its columns stay in the row */
    FILE *trace;                /* NULL: no trace */
    int sample_hz;              /* 0: rows at DAC writes only */
    double sample_t0;           /* sample i falls at sample_t0 + i / sample_hz */
    uint64_t samples;           /* sample rows written since sample_t0 */
    int quanta_per_s;
    uint32_t expected;          /* bit m: member m is one of this session's */
    uint32_t live;              /* bit m: member m takes part (expected, not lost) */
    ls_history to_axis[LS_LINKS], to_main[LS_LINKS];   /* for the status (lab page) */
} ls_world;

void ls_world_init (ls_world *w, uint64_t seed, int sample_hz, FILE *trace);
/* The status after quantum k, one JSON object (the lab page's view of the five
   machines): time, each member taking part or lost, the rack's power, the
   seed and the sample rate, per axis the plant's state
   and the words that last crossed its link each way, with their quanta, and the
   value last sent with each link command ("sent": code -> value). */
void ls_world_status (FILE *f, const ls_world *w, uint64_t k);
int ls_world_step (ls_world *w, uint64_t k, const ls_up *const ups[LS_MEMBERS],
                   const ls_event *const events[LS_MEMBERS],
                   const plant_command *const commands[LS_MEMBERS], ls_down downs[LS_MEMBERS]);

#endif
