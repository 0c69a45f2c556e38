#version 330 core
// Evaluation order naga's GLSL front gets wrong unless rewritten: the right operand of
// && and || runs only when the left one does not decide (parenthesised, nested, in a loop
// condition), and `continue` in a do-while loop evaluates the condition.
in vec2 uv;
out vec4 color;

float calls = 0.0;
bool counted(bool r) { calls += 1.0; return r; }

void main()
{
    bool a = uv.x > 0.5;
    bool b = (a) && (counted(uv.y > 0.5));
    bool c = a || counted(uv.y > 0.25) && counted(uv.x > 0.25);
    int i = 0;
    int odd = 0;
    do {
        i++;
        if (i % 2 == 0)
            continue;
        odd++;
    } while (i < 6 && counted(true));
    if (a)
        do { i--; if (i > 3) continue; } while (i > 0);
    else
        i += 1;
    color = vec4(float(b), float(c), calls / 8.0, float(odd + i) / 8.0);
}
