/* devices.h: what the project's SIMH device files share (glue only; the
   physics is plant.h). See machine_sys.c for how they join SIMH. */
#ifndef DEVICES_H
#define DEVICES_H

#include "pdp11_defs.h"
#include "plant.h"
#include "plant_command.h"
#include "gripper.h"
#include "plant_row.h"
#include "link.h"

/* Time base (time_base.c): simulated time = executed instructions / rate. */
extern int32 clock_rate;                 /* instructions per simulated second */
double clock_time (void);                /* simulated seconds since power-up */
int32 clock_share (int32 per_second, int32 *acc);  /* next interval of an exact n/s series */
void clock_rescale (UNIT *uptr, int32 old_rate);   /* keep an event's simulated time */
/* An exact series of events, each counted from its predecessor's due time (time_base.c
   says why): start it, then activate the unit n instructions after the last due time
   (or the next of per_second a second); rescale when RATE changes. */
typedef struct { int32 acc; double due; } clock_series;
void clock_series_start (clock_series *s);
void clock_series_activate (UNIT *uptr, clock_series *s, int32 n);
void clock_series_next (UNIT *uptr, clock_series *s, int32 per_second);
void clock_series_rescale (UNIT *uptr, clock_series *s, int32 old_rate);
typedef void (*clock_rate_hook) (int32 old_rate);
void clock_on_rate_change (clock_rate_hook before, clock_rate_hook after);
void clock_set_rate (int32 rate);                  /* SET CLK RATE: hooks, new base */

/* Pacing to the host's clock (wall_pacer.c), for the devices asked to. */
typedef struct { int held; double wall0, sim0; } wall_pacer;
double wall_seconds (void);                        /* the host's monotonic clock */
void wall_pacer_pace (wall_pacer *p, double speed, double slack_s);  /* sleep while ahead */
void wall_pacer_drop (wall_pacer *p);              /* the next call takes a new reference */

/* The KDF11-A's instruction times as the time base (kdf11_time.c, SET CLK TIMED). */
extern int32 kdf11_timed;
int kdf11_time_possible (void);                    /* this simulator's CPU prices (pdp11-timed) */
t_stat kdf11_time_set (int on);

/* The clock (kw11l.c): its part of a rate change. */
void kwl_rate_changed (int32 old_rate);

/* Plant glue (plant_dev.c): the plant as the bus devices see it. */
extern plant robot_plant;
void plant_dev_catch_up (void);                   /* integrate up to now */
void plant_dev_dac (int axis, int code);          /* AAV11-A wrote a channel */
void plant_dev_run_lines (int lines);             /* DRV11 OUTBUF bits 3:0 */
uint16 plant_dev_counter (int axis);              /* DRV11 INBUF */
void plant_dev_write_row (FILE *f, int axis);     /* one row (trace, LAB P rows) */
extern gripper robot_gripper;
void plant_dev_gripper_lines (int step, int dir);  /* DRV11 OUTBUF bits 4, 5 */
int plant_dev_gripper_contact (void);             /* DRV11 REQ B */
void plant_dev_power (int on);                    /* the amplifier rack's switch */
int plant_dev_powered (void);
void plant_dev_on_lines_changed (void (*hook) (void));  /* told when a SET moves a line */
void drv11_lines_changed (void);                  /* REQ lines may have moved */
void plant_dev_init (void);
void plant_dev_rate_changing (int32 old_rate);    /* integrate up to now, old time */
void plant_dev_rate_changed (int32 old_rate);     /* pending samples keep their times */
void plant_dev_command_done (void);               /* after each SCP command */
void rack_hint_enable (int on);                   /* SET PLANT HINT (rack_hint.c) */
void rack_hint_dac (int axis, int code, int powered, double from_zero);  /* at each DAC write */

/* Lock-step (simh/lockstep_dev.c): the role of this machine among the five, and
   the plant glue's way to it while a role is set; the links (bus/link_dev.c). */
#define LOCKSTEP_NONE (-1)
extern int lockstep_role;                         /* LOCKSTEP_NONE, 0..3 an axis, 4 MAIN */
void lockstep_dac (int channel, int code);
void lockstep_run_lines (int lines);
uint16 lockstep_counter (void);
void lockstep_rate_changed (int32 old_rate);
/* SET PLANT among the five: checked now, applied by the coordinator at the next
   boundary (NULL), or why not; SHOW PLANT's plant: the coordinator's at the last
   boundary with those settings applied (returns how many are still to come). */
const char *lockstep_plant_command (const plant_command *c);
int lockstep_plant_shown (plant *pl, int *sample_hz);
void link_dev_configure (int links);              /* 0 (absent), 1 (11/03), 4 (11/23) */
link_wire link_dev_take_wire (int i);
void link_dev_deliver (int i, link_wire w);
void link_dev_peer_lost (int i);

/* Text files written by a device (text_attach.c): `what` starts the error message. */
t_stat device_attach_text (UNIT *uptr, char *cptr, const char *what);
void device_detach_text (UNIT *uptr);

/* EXAMINE/DEPOSIT at 160000-177777 reach the I/O page (io_page_examine.c). */
void io_page_examine_install (void);

/* Console input pacing (console_pacing.c). */
void console_pacing_install (void);
void console_pacing_rate_changed (int32 old_rate);

/* The scripted runs' stop at the prompt (prompt_cue.c). */
void prompt_cue_install (void);

/* RL02 write-through (rl_durable.c), one writer per image (rl_one_writer.c). */
void rl_durable_install (void);
void rl_one_writer_install (void);

/* QUIT, EXIT and BYE at sim> FLUSH the FORTH's blocks first (leave_check.c). */
void leave_check_install (void);

/* Interrupts taken per vector (interrupt_count.c); a breakpoint on an I/O
   register (io_break.c: SET LAB IOBREAK). */
void interrupt_count_install (void);
uint32 interrupt_count (int32 vector);
void interrupt_count_write (FILE *f, const char *before);
t_stat io_break_set (char *cptr);
t_stat io_break_clear (void);
void io_break_show (FILE *st);

/* The lab bench's device (lab.c): its part of a rate change. */
void lab_rate_changed (int32 old_rate);

extern DEVICE kwl_dev, drv_dev, aav_dev, plant_dev, lab_dev, cue_dev, lockstep_dev, link_dev[];

/* Byte writes (SIMH passes the byte in data<7:0>, PA<0> says which half). */
#define MERGE_BYTE(old, data, pa, access) \
    (((access) == WRITEB) ? (((pa) & 1) ? (((old) & 0377) | (((data) & 0377) << 8)) \
                                        : (((old) & ~0377) | ((data) & 0377))) : (data))

#endif
