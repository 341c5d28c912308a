(define (problem briefcase-office) (:domain briefcase)
  (:objects home office - location paper dictionary - portable)
  (:init (at-b home) (at paper home) (at dictionary home))
  (:goal (and (at paper office) (at dictionary office) (not (in paper)) (not (in dictionary)) (at-b home))))
