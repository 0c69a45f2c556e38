#version 330 core
// Seed 000's exploding geometry shader takes each face's normal from its edges,
// normalize(cross(edge1, edge2)). Without a geometry stage the same face normal comes from
// the screen-space derivatives of the world position (flat shading): on a triangle seen
// edge-on, or collapsed to a line or a point, both edges are parallel and the cross
// product is the zero vector.

in vec3 vWorldPos;

out vec4 FragColor;

void main()
{
    vec3 edge1 = dFdx(vWorldPos);
    vec3 edge2 = dFdy(vWorldPos);
    vec3 n = normalize(cross(edge1, edge2));
    FragColor = vec4(0.5 + 0.5 * n, 1.0);
}
