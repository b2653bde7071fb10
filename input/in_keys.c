/*
 * in_keys: names of key codes. The codes are the kernel's KEY_* / BTN_*
 * (a stable ABI); libevdev holds the name table, so new kernel keys need no
 * change here.
 */
#include "input/in.h"

#include <stdio.h>
#include <string.h>
#include <strings.h>

#include <libevdev/libevdev.h>

/* Short names people type that are not KEY_<name>. */
static const struct {
	const char *alias;
	int code;
} in_key_aliases[] = {
	{ "space", KEY_SPACE },         { "enter", KEY_ENTER },
	{ "return", KEY_ENTER },        { "esc", KEY_ESC },
	{ "escape", KEY_ESC },          { "ctrl", KEY_LEFTCTRL },
	{ "control", KEY_LEFTCTRL },    { "alt", KEY_LEFTALT },
	{ "shift", KEY_LEFTSHIFT },     { "tab", KEY_TAB },
	{ "backspace", KEY_BACKSPACE },
};

/* KEY_RESERVED (0) and KEY_MAX are in libevdev's table but are no key. */
static int in_key_valid(int code)
{
	return code > KEY_RESERVED && code < KEY_MAX;
}

int in_key_from_name(const char *name)
{
	char up[64];
	size_t n;
	int code;

	if (!name)
		return -1;
	n = strlen(name);
	if (n == 0 || n > 40)
		return -1;
	for (size_t i = 0; i < sizeof(in_key_aliases) / sizeof(in_key_aliases[0]); i++)
		if (strcasecmp(name, in_key_aliases[i].alias) == 0)
			return in_key_aliases[i].code;
	/* libevdev's names are upper case with a KEY_/BTN_ prefix; anything
	 * else ("up", "w", "5", "leftctrl") gets KEY_ put in front. */
	if (strncasecmp(name, "KEY_", 4) == 0 || strncasecmp(name, "BTN_", 4) == 0)
		snprintf(up, sizeof(up), "%s", name);
	else
		snprintf(up, sizeof(up), "KEY_%s", name);
	/* ASCII by hand: the locale must not change what a name means. */
	for (char *p = up; *p; p++) {
		if (*p >= 'a' && *p <= 'z')
			*p = (char)(*p - 'a' + 'A');
		else if (!(*p >= 'A' && *p <= 'Z') && !(*p >= '0' && *p <= '9') && *p != '_')
			return -1;
	}
	code = libevdev_event_code_from_name(EV_KEY, up);
	return in_key_valid(code) ? code : -1;
}

const char *in_key_name(int code)
{
	if (!in_key_valid(code))
		return NULL;
	return libevdev_event_code_get_name(EV_KEY, (unsigned int)code);
}
