// Selects the opaque cream sphere with the chart grid in sphere.frag (one program per look).
#define SPHERE_LOOK 0
