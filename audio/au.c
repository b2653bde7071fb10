/*
 * au: the backend list and the spec parser (contracts in au.h).
 */
#include "audio/au.h"

#include <errno.h>
#include <string.h>

const struct au_backend *const au_backends[] = { &au_alsa, &au_wav, &au_null, NULL };

int au_parse(const char *spec, const char *device, const struct au_backend **be,
	     const char **arg, char *why, size_t whylen)
{
	const char *colon = strchr(spec, ':');
	size_t n = colon ? (size_t)(colon - spec) : strlen(spec);

	for (int i = 0; au_backends[i]; i++) {
		const struct au_backend *b = au_backends[i];
		if (strlen(b->name) != n || strncmp(spec, b->name, n) != 0)
			continue;
		if (b == &au_wav && (!colon || !colon[1])) {
			snprintf(why, whylen, "wav needs a file: wav:FILE");
			return -EINVAL;
		}
		if (b == &au_null && colon) {
			snprintf(why, whylen, "null takes no argument");
			return -EINVAL;
		}
		*be = b;
		*arg = colon ? colon + 1 : b == &au_alsa ? device : "";
		return 0;
	}
	snprintf(why, whylen, "unknown sound output \"%.*s\" (alsa, alsa:DEVICE, wav:FILE, null)",
		 (int)(n > 32 ? 32 : n), spec);
	return -EINVAL;
}
