(define (problem f1) (:domain fridge)
  (:objects s1 s2 s3 - screw b1 - backplane c1 - compressor f1 - fridge)
  (:init (fastened s1) (fastened s2) (fastened s3) (holds s1 b1) (holds s2 b1) (attached b1 f1) (fridge-on f1) (in c1 f1) (covers b1 c1))
  (:goal (and (ok c1) (not (fridge-on f1)))))
