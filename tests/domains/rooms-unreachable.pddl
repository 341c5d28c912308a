; No door leads to the attic: no plan reaches the goal.
(define (problem rooms-unreachable) (:domain rooms)
  (:objects r - robot kitchen hall attic - room)
  (:init (at r kitchen) (door kitchen hall))
  (:goal (at r attic)))
