; The cup and the plate belong in the box; the knife stays out.
(define (problem packing-kitchen) (:domain packing)
  (:objects cup plate knife - item box - box table - surface)
  (:init (hand_empty) (on cup table) (on plate table) (on knife table) (open box)
         (belongs cup box) (belongs plate box))
  (:goal (and (closed box))))
