/* link.h: one end of a DRV11-to-DRV11 parallel link, the cable crossed
   (the project's continuation: docs/controllers.md), as pure logic with no
   SIMH types so it can be tested alone (tests/controllers/lockstep_test.c).
   The bus glue is bus/link_dev.c; the coordinator moves what crossed
   (link_wire) from one end to the other at every quantum boundary.

   CSR as the program reads it:
     bit 15 REQ B      "data taken": the other side read its INBUF
     bit 8  PEER LOST  (the project's addition, not DEC) the machine at the
                       other end has died; only the 11/23's ends set it
     bit 7  REQ A      "new data": the other side wrote its OUTBUF
     bit 6  INT ENB A  read/write        bit 5  INT ENB B  read/write
     bits 1:0          read/write user bits
     other bits read 0; a write changes only the read/write bits
   Writing OUTBUF clears this end's REQ B; the value reaches the other end's
   INBUF at the next boundary and sets its REQ A (several writes within one
   quantum: the last value crosses). Reading INBUF clears this end's REQ A
   and, at the next boundary, sets the other end's REQ B. */
#ifndef LINK_H
#define LINK_H

#include <stdint.h>

#define LINK_REQB     0100000
#define LINK_LOST     0000400
#define LINK_REQA     0000200
#define LINK_IEA      0000100
#define LINK_IEB      0000040
#define LINK_USER     0000003
#define LINK_CSR_RW   (LINK_IEA | LINK_IEB | LINK_USER)

/* What one end did during a quantum: what crosses to the other at its end. */
typedef struct {
    uint8_t sent;       /* OUTBUF written: value crosses */
    uint8_t taken;      /* INBUF read */
    uint16_t value;
} link_wire;

typedef struct {
    uint16_t csr;       /* the read/write bits */
    uint16_t outbuf, inbuf;
    int req_a, req_b, lost;
    link_wire out;      /* gathered since the last boundary */
} link_end;

void link_init (link_end *e);                       /* power-up and bus INIT */
uint16_t link_read_csr (const link_end *e);
void link_write_csr (link_end *e, uint16_t value);
void link_write_outbuf (link_end *e, uint16_t value);
uint16_t link_read_inbuf (link_end *e);
/* At a boundary: hand over what this end did (and forget it) ... */
link_wire link_take_wire (link_end *e);
/* ... and take what the other end did during the same quantum. */
void link_deliver (link_end *e, link_wire in);
void link_set_lost (link_end *e);
int link_int_a (const link_end *e);                 /* INT ENB A and REQ A */
int link_int_b (const link_end *e);                 /* INT ENB B and REQ B */

#endif
