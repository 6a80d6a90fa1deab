// Selects the sphere coloured by a field in sphere.frag (one program per look).
#define SPHERE_LOOK 2
