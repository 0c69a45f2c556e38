#!/usr/bin/env python3
"""simongeilfus/Cinder-Experiments apps: GlslProg::create / GlslProg::Format programs,
stage text as Cinder's ShaderPreprocessor builds it (see cinder_common.py).
Usage: gather_cinder_experiments.py MIRROR_GIT_DIR OUT_DIR"""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror
from cinder_common import gather

m = Mirror(sys.argv[1])
print(gather(m, sys.argv[2], "cinderexp", lambda p: "/blocks/" not in p), "programs")
