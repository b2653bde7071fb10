/* libFuzzer target: the recording format (input/rec.c). The input is
 * written to a file and read back through the real reader; every command
 * read must re-encode to the bytes it came from. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "input/rec.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t len)
{
	static char path[64];
	struct rec_header h;
	struct rec_reader *r;
	struct sim_cmd c;
	char err[256];
	FILE *f;
	size_t off;

	rec_header_decode(data, len, &h, err, sizeof(err));
	if (!path[0])
		snprintf(path, sizeof(path), "/tmp/fuzz_rec.%d", (int)getpid());
	f = fopen(path, "wb");
	if (!f)
		return 0;
	fwrite(data, 1, len, f);
	fclose(f);
	if (rec_reader_open(path, &r, err, sizeof(err)) == 0) {
		off = rec_reader_header(r)->header_size;
		while (rec_reader_next(r, &c) == 1) {
			uint8_t b[REC_CMD_SIZE];
			rec_cmd_encode(b, &c);
			if (off + REC_CMD_SIZE > len || memcmp(b, data + off, REC_CMD_SIZE) != 0)
				abort();
			off += REC_CMD_SIZE;
		}
		rec_check(rec_reader_header(r), 0x1234, err, sizeof(err));
		rec_reader_close(r);
	}
	return 0;
}
