"""CAD files brought into the workbench: STEP (Open CASCADE, through OCP) and DXF (ezdxf).

Domain package: knows nothing of projects, services or the GUI. Readers take the file's bytes
and a `field` (the JSON path or upload that named the file) for their error messages.
"""
