/* plant_row.h: the plant trace's row, one format for every writer (pure C).

   The trace written by the SIMH device PLANT (plant_dev.c), the lab's P rows
   (lab.c) and the lock-step coordinator (lockstep/coordinator.c) share it:
     time_s,axis,dac,vcmd,vel,pos,counter,grip,contact,missed
   simulated seconds, X/Y/Z/T, DAC code, commanded velocity (counts/s),
   velocity (counts/s), position (counts), the counter as a signed 16-bit
   number, then the gripper on every row: opening (inches), contact (0/1),
   step pulses missed so far. */
#ifndef PLANT_ROW_H
#define PLANT_ROW_H

#include <stdio.h>

#include "plant.h"
#include "gripper.h"

extern const char plant_row_columns[];     /* the CSV header, without its newline */
void plant_row_write (FILE *f, const plant *pl, const gripper *g, int axis);

#endif
