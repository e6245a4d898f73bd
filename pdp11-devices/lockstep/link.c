/* link.c: one end of a DRV11-to-DRV11 link (link.h). */
#include "link.h"

void link_init (link_end *e)
{
    link_end zero = { 0 };
    int lost = e->lost;                     /* bus INIT does not revive the peer */
    *e = zero;
    e->lost = lost;
}

uint16_t link_read_csr (const link_end *e)
{
    return e->csr | (e->req_a ? LINK_REQA : 0) | (e->req_b ? LINK_REQB : 0)
         | (e->lost ? LINK_LOST : 0);
}

void link_write_csr (link_end *e, uint16_t value)
{
    e->csr = value & LINK_CSR_RW;
}

void link_write_outbuf (link_end *e, uint16_t value)
{
    e->outbuf = value;
    e->req_b = 0;
    e->out.sent = 1;
    e->out.value = value;
}

uint16_t link_read_inbuf (link_end *e)
{
    e->req_a = 0;
    e->out.taken = 1;
    return e->inbuf;
}

link_wire link_take_wire (link_end *e)
{
    link_wire w = e->out, none = { 0 };
    e->out = none;
    return w;
}

void link_deliver (link_end *e, link_wire in)
{
    if (in.sent) {
        e->inbuf = in.value;
        e->req_a = 1;
    }
    if (in.taken)
        e->req_b = 1;
}

void link_set_lost (link_end *e)
{
    e->lost = 1;
}

int link_int_a (const link_end *e)
{
    return (e->csr & LINK_IEA) && e->req_a;
}

int link_int_b (const link_end *e)
{
    return (e->csr & LINK_IEB) && e->req_b;
}
