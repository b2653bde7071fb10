/*
 * in_sysfs: where an input device sits on USB, from sysfs (contract in
 * in.h). Shared by in_hid (hidraw nodes) and in_evdev (event nodes).
 */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "input/in.h"

/* "1-1.2:1.0": a USB interface directory (bus-port[.port...]:config.iface). */
static bool usb_interface_dir(const char *s, size_t len)
{
	size_t i = 0, colon;
	bool dash = false;

	while (i < len && isdigit((unsigned char)s[i]))
		i++;
	if (i == 0 || i == len || s[i] != '-')
		return false;
	for (i++; i < len && s[i] != ':'; i++) {
		if (!isdigit((unsigned char)s[i]) && s[i] != '.')
			return false;
		dash = true;
	}
	if (!dash || i == len)
		return false;
	colon = i;
	for (i++; i < len; i++)
		if (!isdigit((unsigned char)s[i]) && s[i] != '.')
			return false;
	return colon + 1 < len;
}

/* The component of real ending just before end: its start. */
static const char *component(const char *real, const char *end)
{
	const char *start = end;

	while (start > real && start[-1] != '/')
		start--;
	return start;
}

int in_usb_port(const char *dir, int up, char *port, size_t len)
{
	char real[PATH_MAX];
	char *end;

	if (len)
		port[0] = '\0';
	if (!realpath(dir, real))
		return -errno;
	end = real + strlen(real);
	for (int i = 0; i < up; i++) {
		char *slash = strrchr(real, '/');
		if (!slash || slash == real)
			return 0;
		*slash = '\0';
		end = slash;
	}
	/* the last component, then its parent */
	for (int k = 0; k < 2 && end > real; k++) {
		const char *start = component(real, end);
		if (usb_interface_dir(start, (size_t)(end - start))) {
			size_t n = (size_t)(strchr(start, ':') - start);
			if (n >= len)
				return -ENAMETOOLONG;
			memcpy(port, start, n);
			port[n] = '\0';
			return 0;
		}
		if (start == real || start - 1 == real)
			break;
		end = (char *)start - 1;
	}
	return 0;
}
