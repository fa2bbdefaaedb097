/* The entries' lock (mutex.h). */
#include "mutex.h"

#ifdef _WIN32
#define WIN32_LEAN_AND_MEAN
#include <windows.h>

_Static_assert(sizeof(usrsub_mutex) == sizeof(SRWLOCK), "usrsub_mutex is an SRWLOCK");

void usrsub_mutex_lock(usrsub_mutex *m)
{
    AcquireSRWLockExclusive((PSRWLOCK)m);
}

void usrsub_mutex_unlock(usrsub_mutex *m)
{
    ReleaseSRWLockExclusive((PSRWLOCK)m);
}
#else
void usrsub_mutex_lock(usrsub_mutex *m)
{
    pthread_mutex_lock(m);
}

void usrsub_mutex_unlock(usrsub_mutex *m)
{
    pthread_mutex_unlock(m);
}
#endif
