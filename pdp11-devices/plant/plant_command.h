/* plant_command.h: one SET PLANT setting as data (an axis parameter, the
   rack's power switch, the seed, the trace's sample rate), so that the same
   setting can be applied where the plant lives: on the simulator's own plant
   (plant_dev.c) or, among the five machines in lock-step, carried to the
   coordinator's (lockstep_wire.h) and applied there at a quantum boundary.
   Pure: no SIMH types (tested in tests/controllers/plant_command_test.c).

   plant_command_apply(pl, c): applies c to pl with plant.c's own checks;
   NULL when accepted, else why not, and pl is as it was. PC_SAMPLE is the
   trace's, not the plant's: accepted (0..PLANT_SAMPLE_MAX) and pl untouched;
   the caller keeps the rate. plant_command_text(c, buf, n): the setting as
   it is typed after SET PLANT ("X TAU=20", "POWER=OFF"). */
#ifndef PLANT_COMMAND_H
#define PLANT_COMMAND_H

#include <stddef.h>
#include <stdint.h>

#include "plant.h"

#define PLANT_SAMPLE_MAX 1000             /* trace samples per simulated second */

typedef enum { PC_PARAM, PC_POWER, PC_SEED, PC_SAMPLE } plant_command_kind;

typedef struct {
    uint32_t kind;                        /* plant_command_kind */
    uint32_t axis;                        /* PC_PARAM: AXIS_X..AXIS_T */
    uint32_t which;                       /* PC_PARAM: a plant_param */
    uint32_t pad;
    double value;                         /* PC_PARAM: the value; PC_POWER: 1 on, 0 off;
                                             PC_SAMPLE: samples per second */
    uint64_t seed;                        /* PC_SEED */
} plant_command;

const char *plant_command_apply (plant *pl, const plant_command *c);
void plant_command_text (const plant_command *c, char *buf, size_t n);

#endif
