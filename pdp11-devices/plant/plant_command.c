/* plant_command.c: a SET PLANT setting applied to a plant (plant_command.h). */
#include "plant_command.h"

#include <stdio.h>

#define TEXT_(x) #x
#define TEXT(x) TEXT_(x)                  /* a number's digits, in a message */

const char *plant_command_apply (plant *pl, const plant_command *c)
{
    switch (c->kind) {
    case PC_PARAM:
        if (c->which >= P_COUNT) return "no such parameter";
        return plant_set_param (pl, (int) c->axis, (plant_param) c->which, c->value);
    case PC_POWER:
        plant_set_power (pl, c->value != 0.0);
        return NULL;
    case PC_SEED:
        plant_reseed (pl, c->seed);
        return NULL;
    case PC_SAMPLE:
        if (!(c->value >= 0.0 && c->value <= PLANT_SAMPLE_MAX) || c->value != (double) (int) c->value)
            return "SAMPLE needs a whole number of samples per second, 0.." TEXT (PLANT_SAMPLE_MAX);
        return NULL;
    default:
        return "no such setting";
    }
}

void plant_command_text (const plant_command *c, char *buf, size_t n)
{
    switch (c->kind) {
    case PC_PARAM:
        snprintf (buf, n, "%c %s=%g", c->axis < PLANT_AXES ? plant_axis_names[c->axis] : '?',
                  c->which < P_COUNT ? plant_param_names[c->which] : "?", c->value);
        break;
    case PC_POWER:
        snprintf (buf, n, "POWER=%s", c->value != 0.0 ? "ON" : "OFF");
        break;
    case PC_SEED:
        snprintf (buf, n, "SEED=%llu", (unsigned long long) c->seed);
        break;
    case PC_SAMPLE:
        snprintf (buf, n, "SAMPLE=%g", c->value);
        break;
    default:
        snprintf (buf, n, "?");
    }
}
