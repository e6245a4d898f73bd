/* wire_io.c: whole messages on the lock-step socket (lockstep_wire.h). */
#define _DEFAULT_SOURCE
#include "lockstep_wire.h"

#include <errno.h>
#include <unistd.h>

int ls_io_full (int fd, void *buf, size_t n, int writing)
{
    char *p = buf;
    while (n > 0) {
        ssize_t k = writing ? write (fd, p, n) : read (fd, p, n);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) return 0;
        p += k;
        n -= (size_t) k;
    }
    return 1;
}
