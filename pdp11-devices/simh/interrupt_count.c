/* interrupt_count.c: how many interrupts the CPU took, per vector (the lab's
   front panel shows them per simulated second).

   How, without patching SIMH: when the CPU takes an interrupt, pdp11_io.c's
   get_vector() asks the slot's acknowledge routine for the vector, if the
   device gave one, else uses the slot's vector. Every run rebuilds those slots
   from the devices' DIBs (build_dib_tab), so at start-up (machine_sys.c) each
   vector of each device's DIB gets an acknowledge routine of this file, one
   per DIB vector: it counts the vector the device's own routine (or its DIB)
   gives, and returns it. Only the taking is counted: a request the CPU never
   took (its priority too high) is not. The count follows the instructions, not
   the host: the same run counts the same at any pace.

   Not counted: traps (vectors 4, 10, 14, 20, 30, 34, 250), which the CPU takes
   from its own table with no routine a device could wrap, and the CPU's own
   PIRQ. The FORTH's traps are errors, each reported at the console. */
#include "devices.h"

#define SLOTS 0140                      /* DIB vectors wrapped at most */
#define VECTORS 0400                    /* vector / 4: vectors below 2000 */

extern DEVICE *sim_devices[];

static struct { DIB *dib; int index; int32 (*stock) (void); } slot[SLOTS];
static int slots;
static uint32 taken[VECTORS];

static int32 acknowledge (int n)
{
    DIB *d = slot[n].dib;
    int32 vec = slot[n].stock ? slot[n].stock () : (d->vec ? d->vec + 4 * slot[n].index : 0);
    if (vec > 0 && (vec >> 2) < VECTORS)
        taken[vec >> 2]++;
    return vec;
}

/* One routine per slot: the acknowledge routine has no argument to say which.
   ACK8(01) makes ack_010 ... ack_017, slots 010-017: octal, so the twelve groups
   number the slots 0-0137 without a gap. */
#define ACK(n) static int32 ack_##n (void) { return acknowledge (n); }
#define ACK8(n) ACK(n##0) ACK(n##1) ACK(n##2) ACK(n##3) ACK(n##4) ACK(n##5) ACK(n##6) ACK(n##7)
ACK8(0) ACK8(01) ACK8(02) ACK8(03) ACK8(04) ACK8(05) ACK8(06) ACK8(07) ACK8(010) ACK8(011) ACK8(012) ACK8(013)
#define REF8(n) &ack_##n##0, &ack_##n##1, &ack_##n##2, &ack_##n##3, \
                &ack_##n##4, &ack_##n##5, &ack_##n##6, &ack_##n##7,
static int32 (*const routine[]) (void) = {
    REF8(0) REF8(01) REF8(02) REF8(03) REF8(04) REF8(05) REF8(06) REF8(07) REF8(010) REF8(011)
    REF8(012) REF8(013)
};

void interrupt_count_install (void)
{
    for (int i = 0; sim_devices[i] != NULL; i++) {
        DIB *d = (DIB *) sim_devices[i]->ctxt;
        if (d == NULL)
            continue;
        for (int v = 0; v < d->vnum && v < VEC_DEVMAX; v++) {
            int ours = 0;
            for (int k = 0; k < slots; k++)
                ours |= d->ack[v] == routine[k];
            if (ours)
                continue;                       /* a DIB two devices share: counted once */
            if (slots == SLOTS) {
                fprintf (stderr, "interrupt_count: more than %d vectors; %s's not counted\n",
                         SLOTS, sim_dname (sim_devices[i]));
                return;
            }
            slot[slots].dib = d;
            slot[slots].index = v;
            slot[slots].stock = d->ack[v];
            d->ack[v] = routine[slots++];
        }
    }
}

uint32 interrupt_count (int32 vector)
{
    return vector >= 0 && (vector >> 2) < VECTORS ? taken[vector >> 2] : 0;
}

/* `vector=count` (vector octal) for each vector taken at least once, each after `before`. */
void interrupt_count_write (FILE *f, const char *before)
{
    for (int v = 0; v < VECTORS; v++)
        if (taken[v])
            fprintf (f, "%s%o=%u", before, v << 2, taken[v]);
}
