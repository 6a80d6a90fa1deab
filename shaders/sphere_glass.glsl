// Selects the glassy reference sphere of the ball and circle views in sphere.frag (one program per look).
#define SPHERE_LOOK 1
