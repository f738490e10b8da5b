/* sc_version: the version of the library itself, for a program linked
 * with a shared libspancast that is newer than the header it was compiled
 * against (SPANCAST_VERSION_STRING is that header's).
 */
#include "spancast/spancast.h"

const char *sc_version(void)
{
    return SPANCAST_VERSION_STRING;
}
