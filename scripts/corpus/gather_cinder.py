#!/usr/bin/env python3
"""cinder/Cinder samples/ and test/ apps: GlslProg::create / GlslProg::Format programs,
stage text as Cinder's ShaderPreprocessor builds it (see cinder_common.py).
Usage: gather_cinder.py MIRROR_GIT_DIR OUT_DIR"""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror
from cinder_common import gather

m = Mirror(sys.argv[1])
print(gather(m, sys.argv[2], "cinder", lambda p: p.startswith(("samples/", "test/"))), "programs")
