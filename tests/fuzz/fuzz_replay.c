/* libFuzzer target: the replay-script tokenizer never crashes, and an error
 * names a line inside the script. */
#include <stdint.h>
#include <stdlib.h>

#include "tui/replay.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    tui_replay_script s = { 0 };
    int line = 0;
    char err[512];
    if (tui_replay_parse((const char *)data, size, &s, &line, err, sizeof err) != 0) {
        size_t lines = 1;
        for (size_t i = 0; i < size; i++)
            lines += data[i] == '\n';
        if (line < 1 || (size_t)line > lines)
            abort();
    }
    tui_replay_free(&s);
    return 0;
}
