/*
 * hidsys: the hidraw devices as sysfs lists them (contract in hidsys.h).
 *
 * Why not hid_enumerate: hidapi 0.13's enumeration reads the same sysfs
 * through libudev, and a device that goes away while it runs (an encoder
 * unplugged, a USB port bouncing) can leave it a NULL attribute it does not
 * check: the VM's replug test crashed the daemon inside hid_enumerate. Here
 * every read may fail, and a device that vanished mid-scan is left out.
 */
#include "input/hidsys.h"

#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "input/io.h"

#define HIDSYS_ATTR_MAX 4096   /* a uevent or a string attribute */

/* The text of a small sysfs file, newline cut, into buf; 0 or -errno. */
static int read_attr(const char *path, char *buf, size_t len)
{
	uint8_t *raw;
	size_t n;
	int rc = io_read_file(path, HIDSYS_ATTR_MAX, 0, &raw, &n);

	if (rc < 0)
		return rc;
	while (n && (raw[n - 1] == '\n' || raw[n - 1] == '\0'))
		n--;
	snprintf(buf, len, "%.*s", (int)n, (const char *)raw);
	free(raw);
	return 0;
}

/* The value of KEY= in a uevent text, into out ("" when absent). */
static void uevent_value(const char *text, const char *key, char *out, size_t len)
{
	size_t kl = strlen(key);

	out[0] = '\0';
	for (const char *p = text; p && *p; p = strchr(p, '\n') ? strchr(p, '\n') + 1 : NULL) {
		if (strncmp(p, key, kl) == 0 && p[kl] == '=') {
			const char *v = p + kl + 1, *e = strchr(v, '\n');

			snprintf(out, len, "%.*s", (int)(e ? (size_t)(e - v) : strlen(v)), v);
			return;
		}
	}
}

/* Fills i from the sysfs of hidraw node name; 0, or -errno when the
 * device is gone (or was never a HID device). */
static int describe(const char *sysroot, const char *name, struct in_hid_info *i)
{
	char path[PATH_MAX], text[HIDSYS_ATTR_MAX], id[64], s[128], *end;
	unsigned long bus, vid, pid;

	memset(i, 0, sizeof(*i));
	i->iface = -1;
	snprintf(i->node, sizeof(i->node), "/dev/%.40s", name);   /* names are at most 40 (hidsys_scan) */
	if (snprintf(path, sizeof(path), "%s/class/hidraw/%s/device/uevent", sysroot, name) >=
	    (int)sizeof(path))
		return -ENAMETOOLONG;
	if (read_attr(path, text, sizeof(text)) < 0)
		return -ENODEV;
	/* HID_ID=BBBB:VVVVVVVV:PPPPPPPP, hexadecimal */
	uevent_value(text, "HID_ID", id, sizeof(id));
	bus = strtoul(id, &end, 16);
	if (end == id || *end != ':')
		return -ENODEV;
	vid = strtoul(end + 1, &end, 16);
	if (*end != ':')
		return -ENODEV;
	pid = strtoul(end + 1, &end, 16);
	i->vid = (uint16_t)vid;
	i->pid = (uint16_t)pid;
	uevent_value(text, "HID_UNIQ", i->serial, sizeof(i->serial));
	uevent_value(text, "HID_NAME", i->name, sizeof(i->name));
	if (bus != 0x03)
		return 0;
	/* USB: the HID device sits in its interface, in its USB device; the
	 * strings are the USB device's, as hidapi shows them */
	snprintf(path, sizeof(path), "%s/class/hidraw/%s/device/../bInterfaceNumber", sysroot,
		 name);
	if (read_attr(path, s, sizeof(s)) == 0) {
		long n = strtol(s, &end, 16);

		if (end != s && n >= 0 && n < 256)
			i->iface = (int)n;
	}
	{
		char man[64] = "", prod[64] = "";   /* both fit in the name */

		snprintf(path, sizeof(path), "%s/class/hidraw/%s/device/../../manufacturer",
			 sysroot, name);
		if (read_attr(path, man, sizeof(man)) < 0)
			man[0] = '\0';
		snprintf(path, sizeof(path), "%s/class/hidraw/%s/device/../../product", sysroot,
			 name);
		if (read_attr(path, prod, sizeof(prod)) < 0)
			prod[0] = '\0';
		if (man[0] || prod[0])
			snprintf(i->name, sizeof(i->name), "%s%s%s", man, man[0] && prod[0] ? " " : "",
				 prod);
	}
	return 0;
}

static long node_number(const char *node)
{
	const char *b = strrchr(node, '/');

	b = b ? b + 1 : node;
	return strncmp(b, "hidraw", 6) == 0 ? strtol(b + 6, NULL, 10) : LONG_MAX;
}

static int cmp_node(const void *a, const void *b)
{
	long x = node_number(((const struct in_hid_info *)a)->node);
	long y = node_number(((const struct in_hid_info *)b)->node);

	return (x > y) - (x < y);
}

int hidsys_scan(const char *sysroot, struct in_hid_info **out, size_t *count)
{
	char dir[PATH_MAX];
	struct in_hid_info *l = NULL;
	size_t n = 0, cap = 0;
	struct dirent *de;
	DIR *dh;

	*out = NULL;
	*count = 0;
	if (snprintf(dir, sizeof(dir), "%s/class/hidraw", sysroot) >= (int)sizeof(dir))
		return -ENAMETOOLONG;
	dh = opendir(dir);
	if (!dh)
		return errno == ENOENT ? 0 : -errno;   /* no hidraw driver: no devices */
	while ((de = readdir(dh)) != NULL) {
		if (strncmp(de->d_name, "hidraw", 6) != 0 || strlen(de->d_name) > 40)
			continue;
		if (n == cap) {
			struct in_hid_info *nl;

			cap = cap ? cap * 2 : 8;
			nl = realloc(l, cap * sizeof(*l));
			if (!nl) {
				free(l);
				closedir(dh);
				return -ENOMEM;
			}
			l = nl;
		}
		if (describe(sysroot, de->d_name, &l[n]) == 0)
			n++;
	}
	closedir(dh);
	if (n > 1)
		qsort(l, n, sizeof(*l), cmp_node);
	*out = l;
	*count = n;
	return 0;
}
