/* libFuzzer target: the scene parser never crashes and every rejection says
 * where (NAME:LINE:). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "scene/scene.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    adh_config cfg;
    adh_config_default(&cfg);
    char why[1024] = "";
    if (adh_scene_parse_string(text, "fuzz", &cfg, why, sizeof why) != 0 && strncmp(why, "fuzz:", 5) != 0)
        abort(); /* an error without its file:line */
    free(text);
    return 0;
}
