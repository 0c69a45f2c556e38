#pragma once
const float PI = 3.14159265;
const float INV_PI = 1.0 / PI;
