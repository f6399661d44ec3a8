"""Readers of the printers' own files written from the public specifications only, never from
the product's writers: the independent check of what the writers make (tests/python/
test_printer_files.py).

    ctb.read_ctb(path) -> CtbFile                          Chitubox .ctb, versions 2 to 4
    photon_workshop.read_photon_workshop(path) -> PwFile   Anycubic Photon Workshop (.pwmx, .pwmb,
                                                           .pm4n, .pm5s, ...), versions 1, 515 to 518

Each returns the header's fields, the previews, the layer definitions and layer_image(k), layer
k's mask as a numpy uint8 array (rows x columns, the grey levels the printer's readers decode).
Anything the specification does not allow (a wrong magic or section mark, a table or layer
outside the file, runs that do not fill the image exactly) raises ValueError, in words.
"""
