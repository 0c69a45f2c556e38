#version 100
#extension GL_OES_EGL_image_external : require
precision mediump float;

// A camera or video frame imported as an external image.
uniform samplerExternalOES frame;
varying vec2 uv;

void main()
{
    vec3 c = texture2D(frame, uv).rgb;
    float grey = dot(c, vec3(0.299, 0.587, 0.114));
    gl_FragColor = vec4(vec3(grey), 1.0);
}
