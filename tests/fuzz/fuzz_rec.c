/* libFuzzer target: the recording format (input/rec.c), versions 1 and 2,
 * with and without a start snapshot. The input is written to a file and
 * read back through the real reader; every record read must re-encode to
 * the bytes it came from, and a snapshot the reader accepts must be the
 * bytes after the 80-byte header. */
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
	struct rec_tick t;
	char err[256];
	FILE *f;
	size_t off, rs;

	rec_header_decode(data, len, &h, err, sizeof(err));
	if (!path[0])
		snprintf(path, sizeof(path), "/tmp/fuzz_rec.%d", (int)getpid());
	f = fopen(path, "wb");
	if (!f)
		return 0;
	fwrite(data, 1, len, f);
	fclose(f);
	if (rec_reader_open(path, &r, err, sizeof(err)) == 0) {
		const struct rec_header *rh = rec_reader_header(r);
		struct rec_verify v;
		struct rec_run run;

		/* the snapshot follows the version's fixed header */
		size_t snap_at = rh->version >= REC_VERSION_3 ? REC_HEADER_SIZE_V3 : REC_HEADER_SIZE_V2;

		off = rh->header_size;
		rs = rec_record_size(rh->hash_flags);
		if (rh->snapshot_len &&
		    (!rh->snapshot || (size_t)snap_at + rh->snapshot_len > len ||
		     memcmp(rh->snapshot, data + snap_at, rh->snapshot_len) != 0))
			abort();
		rec_run_from_header(rh, &run);
		rec_verify_init(&v, rh, &run);
		while (rec_reader_next_tick(r, &t) == 1) {
			uint8_t b[REC_CMD_SIZE];
			struct rec_tick mine = { 0 };

			rec_cmd_encode(b, &t.cmd);
			if (off + rs > len || memcmp(b, data + off, REC_CMD_SIZE) != 0)
				abort();
			mine.cmd = t.cmd;
			rec_verify_tick(&v, (uint32_t)((off - rh->header_size) / rs), &t, &mine);
			off += rs;
		}
		rec_verify_summary(&v, err, sizeof(err));
		rec_check(rh, 0x1234, err, sizeof(err));
		rec_check_run(rh, &run, err, sizeof(err));
		rec_reader_close(r);
	}
	return 0;
}
