/* plant_row.c: the plant trace's row (plant_row.h). */
#include "plant_row.h"

const char plant_row_columns[] = "time_s,axis,dac,vcmd,vel,pos,counter,grip,contact,missed";

void plant_row_write (FILE *f, const plant *pl, const gripper *g, int axis)
{
    const plant_axis *a = &pl->ax[axis];
    fprintf (f, "%.9f,%c,%d,%.3f,%.3f,%.3f,%d,%.2f,%d,%lu\n", pl->now,
             plant_axis_names[axis], a->code, plant_vcmd (pl, axis), a->v, a->p,
             (int) (int16_t) plant_counter (pl, axis), gripper_opening (g),
             gripper_contact (g), g->missed);
}
