include <dibond_config.scad>
