; The express trip f0 -> f2 costs 10; two local hops cost 1 each.
(define (problem elevators-1) (:domain elevators)
  (:objects f0 f1 f2 - floor p1 - passenger)
  (:init (lift-at f0) (at p1 f0) (= (total-cost) 0)
         (= (travel f0 f0) 0) (= (travel f0 f1) 1) (= (travel f0 f2) 10)
         (= (travel f1 f0) 1) (= (travel f1 f1) 0) (= (travel f1 f2) 1)
         (= (travel f2 f0) 10) (= (travel f2 f1) 1) (= (travel f2 f2) 0))
  (:goal (and (at p1 f2)))
  (:metric minimize (total-cost)))
