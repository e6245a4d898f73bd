/* lockstep_wire.h: the messages between the five simulators and the lock-step
   coordinator (build/lockstep-coordinator), over a Unix stream socket; both
   ends are built from this header on the same host, so the structs travel as
   they are in memory. The protocol and why: docs/controllers.md.

   Members: 0..3 the LSI-11/03 of axis x, y, z, t; 4 the 11/23 (MAIN).
   ATTACH LOCKSTEP (simh/lockstep_dev.c) connects, at simulated time 0:
     member -> coordinator  ls_hello
     coordinator -> member  ls_welcome (the quantum, the plant at time 0)
   At the end of quantum k (simulated time k / quanta_per_s) every member:
     member -> coordinator  ls_up, then n_events ls_event (its DAC writes and
                            run-line changes in the quantum, times exact),
                            then n_commands plant_command (SET PLANT typed at
                            its sim> in the quantum: applied at the boundary)
     coordinator -> member  ls_down: the plant at the boundary, what crossed
                            its links, which peers are lost, or the end; how
                            many of its SETs the boundary refused
   A member waits for its ls_down before it runs quantum k + 1: no member
   starts a quantum before every live member has finished the one before. */
#ifndef LOCKSTEP_WIRE_H
#define LOCKSTEP_WIRE_H

#include <stddef.h>
#include <stdint.h>

#include "plant.h"
#include "plant_command.h"
#include "link.h"

#define LS_MAGIC       0x4c533231u       /* "LS21" */
#define LS_MAIN        4
#define LS_MEMBERS     5
#define LS_LINKS       4                 /* the 11/23 has one per axis; an 11/03 uses [0] */
#define LS_QUANTA_PER_S 1000             /* 1 simulated ms: the plant's grid step */
#define LS_MAX_EVENTS  1024              /* per member and quantum */
#define LS_MAX_COMMANDS 32               /* SET PLANT settings per member and quantum */
#define LS_END         1u                /* ls_down.flags: the session is over */

enum { LS_EV_DAC, LS_EV_RUN };

typedef struct {
    double t;                            /* simulated seconds */
    uint16_t kind, axis, value, pad;     /* LS_EV_DAC: value = code; LS_EV_RUN: 0 or 1 */
} ls_event;

typedef struct {
    uint32_t magic, member;
    int32_t pid, pad;
} ls_hello;

typedef struct {
    uint32_t magic, quanta_per_s;
    uint32_t sample_hz, pad;
    plant pl;
} ls_welcome;

typedef struct {
    uint64_t quantum;
    uint32_t n_events, n_commands;
    link_wire links[LS_LINKS];
} ls_up;

typedef struct {
    uint64_t quantum;
    uint32_t flags, lost;                /* lost: bit a = the 11/03 of axis a is gone */
    uint32_t refused;                    /* this member's SETs of the quantum not applied */
    uint32_t sample_hz;                  /* the trace's samples per second (SHOW PLANT) */
    link_wire links[LS_LINKS];
    plant pl;
} ls_down;

/* Read (writing 0) or write all n bytes, going on after signals: 1, or 0 when
   the other end is gone (wire_io.c). */
int ls_io_full (int fd, void *buf, size_t n, int writing);

#endif
