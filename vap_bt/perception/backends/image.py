"""A frame as the image a model is shown: lossless PNG in base64, named by a hash.

A :class:`~vap_bt.robot.frame.Frame` carries ``rgb`` as an (H, W, 3) uint8 array in RGB order.
It is encoded losslessly as PNG with OpenCV (which writes BGR, hence the channel swap), so the
model sees exactly the pixels the robot captured.

Records name the image by the SHA-1 of the ``rgb`` array's bytes (C order), not of the PNG:
anyone holding the frame can match a record to it without re-encoding, whatever OpenCV's
version; the size is recorded beside it. The same hash keys a small cache, because every
question of a round (five paraphrases, the sufficiency and viewpoint prompts) is about one frame
and would otherwise encode it seven times.
"""

from __future__ import annotations

import base64
import hashlib
import threading
from collections import OrderedDict
from dataclasses import dataclass

import cv2
import numpy as np


@dataclass(frozen=True)
class EncodedImage:
    """One frame's pixels as sent: PNG bytes in base64, with the hash and size of the rgb array."""

    sha1: str  # of the rgb array's bytes
    width: int
    height: int
    png_b64: str
    mime: str = "image/png"

    def data_url(self) -> str:
        """The image as a ``data:`` URL, the way OpenAI-compatible servers take an inline image."""
        return f"data:{self.mime};base64,{self.png_b64}"


def rgb_sha1(rgb: np.ndarray) -> str:
    """The hash records name a frame by: SHA-1 of the rgb array's bytes in C order."""
    return hashlib.sha1(np.ascontiguousarray(rgb).tobytes()).hexdigest()


def encode_png(rgb: np.ndarray) -> EncodedImage:
    """Encode an (H, W, 3) uint8 RGB array; anything else is a ValueError naming what it got."""
    if not isinstance(rgb, np.ndarray) or rgb.dtype != np.uint8 or rgb.ndim != 3 or rgb.shape[2] != 3:
        got = f"{rgb.dtype} {rgb.shape}" if isinstance(rgb, np.ndarray) else type(rgb).__name__
        raise ValueError(f"frame rgb must be an (H, W, 3) uint8 array, got {got}")
    ok, png = cv2.imencode(".png", cv2.cvtColor(rgb, cv2.COLOR_RGB2BGR))
    if not ok:
        raise ValueError("OpenCV could not encode the frame as PNG")
    return EncodedImage(sha1=rgb_sha1(rgb), width=rgb.shape[1], height=rgb.shape[0],
                        png_b64=base64.b64encode(png.tobytes()).decode("ascii"))


class ImageCache:
    """The last few encoded frames, keyed by hash and shape; safe to use from several threads."""

    def __init__(self, size: int = 8) -> None:
        self.size = size
        self._images: OrderedDict[tuple[str, tuple[int, ...]], EncodedImage] = OrderedDict()
        self._lock = threading.Lock()

    def encode(self, rgb: np.ndarray) -> EncodedImage:
        """``rgb`` as a PNG, encoded once per distinct image (the least recently used beyond ``size``
        forgotten); safe from many threads."""
        key = (rgb_sha1(rgb), rgb.shape) if isinstance(rgb, np.ndarray) else None
        with self._lock:
            if key in self._images:
                self._images.move_to_end(key)
                return self._images[key]
        image = encode_png(rgb)  # outside the lock: encoding is the slow part
        with self._lock:
            self._images[key] = image
            while len(self._images) > self.size:
                self._images.popitem(last=False)
        return image
